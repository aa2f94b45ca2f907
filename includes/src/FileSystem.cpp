// SPDX-License-Identifier: Apache-2.0
// Lexical path helpers shared by the file systems and the include search.
#include "varc/includes/FileSystem.h"

#include <string_view>
#include <vector>

namespace varc::includes {

namespace {

// Applies one segment to |parts|: "." and "" vanish, ".." pops a real segment when there is
// one, and is kept (relative) or dropped (absolute, "/.." is "/") otherwise.
void applySegment(std::vector<std::string_view>& parts, std::string_view segment, bool absolute) {
    if (segment.empty() || segment == ".") return;
    if (segment == "..") {
        if (!parts.empty() && parts.back() != "..") {
            parts.pop_back();
        } else if (!absolute) {
            parts.push_back(segment);
        }
        return;
    }
    parts.push_back(segment);
}

}  // namespace

std::string normalizePath(const std::string& path) {
    if (path.empty()) return "";
    bool absolute = path.front() == '/';
    std::vector<std::string_view> parts;
    std::string_view rest(path);
    while (!rest.empty()) {
        size_t slash = rest.find('/');
        applySegment(parts, rest.substr(0, slash), absolute);
        rest = slash == std::string_view::npos ? std::string_view() : rest.substr(slash + 1);
    }
    std::string result = absolute ? "/" : "";
    for (size_t i = 0; i < parts.size(); ++i) {
        if (i > 0) result += '/';
        result += parts[i];
    }
    return result.empty() ? "." : result;
}

std::string parentPath(const std::string& path) {
    size_t slash = path.rfind('/');
    if (slash == std::string::npos) return "";
    if (slash == 0) return "/";
    return path.substr(0, slash);
}

std::string joinPath(const std::string& dir, const std::string& name) {
    if (name.empty()) return normalizePath(dir);
    if (dir.empty() || name.front() == '/') return normalizePath(name);
    return normalizePath(dir + "/" + name);
}

}  // namespace varc::includes
