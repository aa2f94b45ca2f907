// SPDX-License-Identifier: Apache-2.0
// How much of each pack `varc validate` compared with the reference: the variants drawn in the
// scenes that matched, per pack and per LightMode.
#pragma once

#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "varc/reader/Pack.h"

namespace varc::cli {

// Prints one line per pack, e.g.
//   library.svpack: 74 of 106 variants compared with the reference (ForwardBase 5/6, ...)
// |compared| holds VariantView::describe() of every variant drawn in a scene that matched. With
// |listUncovered|, each variant not compared follows its pack's line, indented.
void printValidationCoverage(const std::vector<runtime::Pack>& packs,
                             const std::vector<std::string>& packPaths,
                             const std::set<std::string>& compared, bool listUncovered,
                             std::ostream& out);

}  // namespace varc::cli
