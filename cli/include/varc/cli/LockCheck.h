// SPDX-License-Identifier: Apache-2.0
// Compares current variant counts with a lock file: the CI gate behind `varc check`.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "varc/cli/LockFile.h"
#include "varc/cli/Options.h"
#include "varc/core/Diagnostic.h"
#include "varc/frontend/ShaderLoader.h"

namespace varc::cli {

// How strict the gate is. Default: every shader's and pass's count must equal the lock.
// maxGrowth: each shader may grow by at most N variants (or N% of its locked count); shrinking
// passes. budget: each shader may have at most N variants, whatever the lock says.
struct CheckPolicy {
    std::optional<GrowthLimit> maxGrowth;
    std::optional<uint64_t> budget;
};

// Reports each difference as a diagnostic located at the pass (or the pragma whose set changed,
// as a note) and returns true when the gate passes. Differences that the policy allows are
// reported as warnings; the rest as errors.
//
// Example: lock says pass 1 has 5 variants, the shader now says `multi_compile_fwdadd_fullshadows`:
//   a.shader:30:3: error: shader "Custom/A" pass 1 (LightMode ForwardAdd): 13 variants, lock has 5
//   (+8) a.shader:41:4: note: keyword set added: multi_compile_fwdadd_fullshadows: _ SHADOWS_SOFT
bool checkAgainstLock(const LockFile& lock, const std::vector<frontend::LoadedShader>& shaders,
                      const CheckPolicy& policy, DiagnosticSink& sink);

}  // namespace varc::cli
