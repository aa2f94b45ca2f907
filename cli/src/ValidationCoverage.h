// SPDX-License-Identifier: Apache-2.0
// How much of each pack `varc validate` compared with the reference: the variants drawn in the
// scenes that matched, per pack and per LightMode.
#pragma once

#include <cstddef>
#include <map>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "varc/reader/Pack.h"

namespace varc::cli {

struct CoverageTally {
    size_t compared = 0, total = 0;
};

// One pack's coverage: all its variants, and per LightMode ("" = no LightMode tag).
struct PackCoverage {
    std::string packName;  // the pack file's name, without its folder
    CoverageTally all;
    std::map<std::string, CoverageTally> byLightMode;
    std::vector<std::string> uncovered;  // VariantView::describe() of each variant not compared
};

// Counts, per pack, the variants whose VariantView::describe() is in |compared| (the variants
// drawn in scenes that matched). |packPaths| name |packs|, in the same order.
std::vector<PackCoverage> computeValidationCoverage(const std::vector<reader::Pack>& packs,
                                                    const std::vector<std::string>& packPaths,
                                                    const std::set<std::string>& compared);

// "ForwardAdd 8/27, ForwardBase 4/14" ("no LightMode" for untagged passes).
std::string lightModeSummary(const PackCoverage& coverage);

// Prints one line per pack, e.g.
//   library.svpack: 74 of 106 variants compared with the reference (ForwardBase 5/6, ...)
// |compared| holds VariantView::describe() of every variant drawn in a scene that matched. With
// |listUncovered|, each variant not compared follows its pack's line, indented.
void printValidationCoverage(const std::vector<reader::Pack>& packs,
                             const std::vector<std::string>& packPaths,
                             const std::set<std::string>& compared, bool listUncovered,
                             std::ostream& out);

}  // namespace varc::cli
