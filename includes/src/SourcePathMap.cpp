// SPDX-License-Identifier: Apache-2.0
// How a pack records source paths, so that checkouts at different places build the same bytes.
#include "varc/includes/SourcePathMap.h"

#include <filesystem>

namespace varc::includes {

namespace {

// |prefix| is |path| itself or its leading directories ("/a/b" of "/a/b/c", not of "/a/bc").
bool hasPathPrefix(std::string_view path, std::string_view prefix) {
    if (prefix.empty() || path.substr(0, prefix.size()) != prefix) return false;
    return path.size() == prefix.size() || prefix.back() == '/' || path[prefix.size()] == '/';
}

}  // namespace

bool SourcePathMap::addRule(std::string_view rule) {
    size_t equals = rule.find('=');
    if (equals == std::string_view::npos || equals == 0) return false;
    mRules.emplace_back(std::string(rule.substr(0, equals)), std::string(rule.substr(equals + 1)));
    return true;
}

std::string SourcePathMap::map(const std::string& path) const {
    for (auto rule = mRules.rbegin(); rule != mRules.rend(); ++rule) {
        if (hasPathPrefix(path, rule->first)) return rule->second + path.substr(rule->first.size());
    }
    if (mRoot.empty() || path.empty() || path[0] != '/') return path;
    std::filesystem::path normal = std::filesystem::path(path).lexically_normal();
    std::filesystem::path relative = normal.lexically_relative(
        std::filesystem::path(mRoot).lexically_normal());
    if (relative.empty() || *relative.begin() == "..") return path;
    return relative.generic_string();
}

}  // namespace varc::includes
