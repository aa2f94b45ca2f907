// SPDX-License-Identifier: Apache-2.0
// Keyword lists as users read and write them.
#pragma once

#include <string>
#include <vector>

namespace varc {

// |keywords| (a keyword set in declared order) with the no-keyword entry "" written `_`, as in
// the pragma: {"", "FOG_ON"} -> {"_", "FOG_ON"}.
std::vector<std::string> displayKeywords(const std::vector<std::string>& keywords);

}  // namespace varc
