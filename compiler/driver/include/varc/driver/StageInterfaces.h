// SPDX-License-Identifier: Apache-2.0
// Every fragment input must be written by the stage before rasterisation, in every variant.
#pragma once

#include <cstdint>
#include <functional>
#include <set>
#include <utility>
#include <vector>

#include "varc/core/Stage.h"
#include "varc/pack/PackModel.h"

namespace varc::driver {

// What a mismatch reports: the variant, the stage that feeds the fragment program, and the
// fragment input none of that stage's outputs matches in location and type.
using InterfaceMismatchReport = std::function<void(const pack::PackVariant& variant, Stage producer,
                                                   const pack::StageVariable& input)>;

// Checks |variants| (program slots index |programs|) and calls |report| for each fragment input
// the last stage before rasterisation (domain, else geometry, else vertex) does not write. Each
// (producer, fragment) program pair is checked once across calls sharing |checked|; pairs with a
// placeholder program (another shard's, PartialPack.h) are left for `varc merge`. Returns false
// when anything was reported.
bool checkVariantInterfaces(const std::vector<pack::PackVariant>& variants,
                            const std::vector<pack::PackProgram>& programs,
                            std::set<std::pair<uint32_t, uint32_t>>& checked,
                            const InterfaceMismatchReport& report);

}  // namespace varc::driver
