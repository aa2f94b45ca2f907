// SPDX-License-Identifier: Apache-2.0
// Componentwise GLSL.std.450 math on matrices, which glslang emits for HLSL and SPIR-V forbids.
#pragma once

#include <cstdint>
#include <vector>

namespace varc::driver {

// HLSL applies its componentwise intrinsics (lerp, saturate, abs, pow, max, ...) to matrices
// element by element, and glslang translates them to one GLSL.std.450 instruction whose result
// type is the matrix (`%m = OpExtInst %mat3v3float %glsl FMix %a %b %w`), which the validator
// rejects: those instructions take scalars and vectors only. This rewrites each such
// instruction into one per column plus an OpCompositeConstruct under the original result id:
//   %a0 = OpCompositeExtract %v3float %a 0   ... (for each matrix operand and column)
//   %m0 = OpExtInst %v3float %glsl FMix %a0 %b0 %w   (an operand of the column type, such as
//   ...                                               glslang's splatted scalar, is reused)
//   %m  = OpCompositeConstruct %mat3v3float %m0 %m1 %m2
// MatrixInverse (a real matrix operation) and instructions with an operand of any other type
// are left alone. Returns |spirv| itself, word for word, when there is nothing to rewrite or it
// cannot be parsed, so every other module compiles exactly as before.
std::vector<uint32_t> splitMatrixExtendedMath(const std::vector<uint32_t>& spirv);

}  // namespace varc::driver
