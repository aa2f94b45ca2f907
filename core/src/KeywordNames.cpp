// SPDX-License-Identifier: Apache-2.0
// Keyword lists as users read and write them.
#include "varc/core/KeywordNames.h"

namespace varc {

std::vector<std::string> displayKeywords(const std::vector<std::string>& keywords) {
    std::vector<std::string> shown;
    for (const std::string& keyword : keywords) shown.push_back(keyword.empty() ? "_" : keyword);
    return shown;
}

}  // namespace varc
