// SPDX-License-Identifier: Apache-2.0
// The largest variant space a command enumerates: counting is exact without enumerating, but
// listing or building 2^40 variants would run out of memory or time instead of saying so.
#pragma once

#include <cstdint>

#include "varc/core/Diagnostic.h"
#include "varc/frontend/ShaderLoader.h"

namespace varc::frontend {

// The default of --max-variants: per pass.
inline constexpr uint64_t kDefaultMaxVariantsPerPass = 10'000'000;

// Returns true when |pass| has at most |limit| variants. Otherwise reports, at the pass's
// program block, "pass 0 of shader "X" has 1099511627776 variants (40 keyword sets); the limit is
// 10000000 (--max-variants)" with a note at each of the (up to three) largest keyword sets, and
// returns false. Only counts: never enumerates.
bool checkVariantLimit(const LoadedShader& shader, const LoadedPass& pass, uint64_t limit,
                       DiagnosticSink& sink);

}  // namespace varc::frontend
