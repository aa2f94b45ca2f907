// SPDX-License-Identifier: Apache-2.0
// Groups of #define/#undef lines only, and the names each defines.
#include "DefineGroups.h"

#include <algorithm>
#include <string_view>
#include <unordered_map>

namespace varc::driver::projection {

void markDefineGroups(std::vector<PpLine>& lines) {
    using Kind = PpLine::Kind;
    struct Open {
        size_t start;
        bool definesOnly = true;
        std::vector<std::string_view> defines;
    };
    std::vector<Open> open;
    for (size_t i = 0; i < lines.size(); ++i) {
        const PpLine& line = lines[i];
        switch (line.kind) {
            case Kind::If:
            case Kind::Ifdef:
            case Kind::Ifndef:
                open.push_back({i, true, {}});
                break;
            case Kind::Elif:
            case Kind::Else:
                if (open.empty()) return;
                break;
            case Kind::Endif: {
                if (open.empty()) return;
                Open group = std::move(open.back());
                open.pop_back();
                if (!open.empty()) {
                    Open& outer = open.back();
                    outer.definesOnly = outer.definesOnly && group.definesOnly;
                    outer.defines.insert(outer.defines.end(), group.defines.begin(),
                                         group.defines.end());
                }
                if (!group.definesOnly) break;
                std::sort(group.defines.begin(), group.defines.end());
                group.defines.erase(std::unique(group.defines.begin(), group.defines.end()),
                                    group.defines.end());
                lines[group.start].definesOnly = true;
                lines[group.start].defines = std::move(group.defines);
                break;
            }
            case Kind::Define:
            case Kind::Undef:
                if (!open.empty()) open.back().defines.push_back(line.name);
                break;
            case Kind::Text:
                if (!open.empty() && !line.code.empty()) open.back().definesOnly = false;
                break;
            default:  // #pragma, #include, #line, #error...
                if (!open.empty()) open.back().definesOnly = false;
        }
    }
}

}  // namespace varc::driver::projection
