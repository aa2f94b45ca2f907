// SPDX-License-Identifier: Apache-2.0
// Make-style dependency files (`varc build --depfile`), for build systems such as CMake/Ninja.
#include "varc/driver/Depfile.h"

#include <set>

namespace varc::driver {

namespace {

std::string escape(const std::string& path) {
    std::string escaped;
    for (char c : path) {
        if (c == ' ' || c == '#') escaped += '\\';
        if (c == '$') escaped += '$';
        escaped += c;
    }
    return escaped;
}

}  // namespace

std::string makeDepfile(const std::string& target, const std::vector<std::string>& dependencies) {
    std::string text = escape(target) + ":";
    std::set<std::string> seen;
    for (const std::string& dependency : dependencies) {
        if (!seen.insert(dependency).second) continue;
        text += " \\\n  " + escape(dependency);
    }
    return text + "\n";
}

}  // namespace varc::driver
