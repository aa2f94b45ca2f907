// SPDX-License-Identifier: Apache-2.0
// How a pack records source paths, so that checkouts at different places build the same bytes.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace varc::includes {

// Maps a path as varc read it to the path a pack records (source info, dependencies, the inputs
// hash), as compilers do for debug info (GCC's -ffile-prefix-map):
//  1. the last --file-prefix-map OLD=NEW whose OLD is a leading part of the path (whole path
//     components) replaces it with NEW;
//  2. otherwise an absolute path inside |root| is made relative to it;
//  3. anything else is recorded as read.
// Example: root "/src/game", rule "/opt/sdk=sdk": "/src/game/Assets/a.shader" records as
// "Assets/a.shader", "/opt/sdk/inc/b.cginc" as "sdk/inc/b.cginc", "../x.cginc" as is.
class SourcePathMap {
public:
    SourcePathMap() = default;  // records every path as read
    explicit SourcePathMap(std::string root) : mRoot(std::move(root)) {}

    // Parses "OLD=NEW" (OLD non-empty); false when |rule| has no '=' or OLD is empty.
    bool addRule(std::string_view rule);

    std::string map(const std::string& path) const;

private:
    std::string mRoot;  // absolute, or "" for none
    std::vector<std::pair<std::string, std::string>> mRules;
};

}  // namespace varc::includes
