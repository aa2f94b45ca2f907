// SPDX-License-Identifier: Apache-2.0
// Small, fully featured PackContents for the pack tests (already in the writer's normal form).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "varc/pack/PackModel.h"

namespace varc::packtest {

// SPIR-V-shaped words: a valid header, then |words| - 5 instruction-like words derived from
// |seed|, similar across seeds (so a dictionary helps) but distinct per seed.
std::vector<uint32_t> fakeSpirv(uint32_t seed, size_t words = 160);

// The key of |names| in |table| (names must be in the table).
variants::VariantKey keyOf(const std::vector<std::string>& table,
                           const std::vector<std::string>& names);

// Three shaders: "Custom/Lit" (ForwardBase with 5 keyword sets = 16 variants, ForwardAdd with
// a 5-way light set and property-driven render state, ShadowCaster), "Custom/Unlit" (one pass,
// no keywords, sharing a vertex program with Lit) and "Custom/Empty" (a pass without
// variants). Programs are listed in first-use order and all used, so serialize + decode
// returns exactly this.
pack::PackContents makeSampleContents();

}  // namespace varc::packtest
