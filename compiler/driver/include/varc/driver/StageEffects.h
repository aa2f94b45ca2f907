// SPDX-License-Identifier: Apache-2.0
// Which keyword sets turned out to change which stage's program (derived, not declared).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "varc/driver/CompileDriver.h"
#include "varc/variants/VariantSpace.h"

namespace varc::driver {

// For each set of |space| (declaration order), the stages whose program differs between two
// variants that differ only in that set's choice. Example: `multi_compile _ VERTEXLIGHT_ON` used
// only inside the vertex program yields stageBit(Stage::Vertex); a set that no stage tests yields
// 0. |variants| are the pass's compiled variants (any order).
std::vector<StageMask> computeSetStageEffects(const variants::VariantSpace& space,
                                              const std::vector<pack::PackVariant>& variants);

}  // namespace varc::driver
