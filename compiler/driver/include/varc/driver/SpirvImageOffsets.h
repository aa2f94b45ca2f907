// SPDX-License-Identifier: Apache-2.0
// Image offsets that became constants after optimisation, marked ConstOffset as Vulkan requires.
#pragma once

#include <cstdint>
#include <vector>

namespace varc::driver {

// HLSL lets `t.Sample(s, uv, offset)` take an offset that is constant only once an [unroll]
// loop is unrolled (`for (int i = -2; i < 0; i++) t.Sample(s, uv, int2(i, 0))`), and the DirectX
// compilers unroll before they check. glslang emits such an offset as the `Offset` image
// operand, which Vulkan allows only on gathers (VUID-StandaloneSpirv-Offset-04663), even after
// spirv-opt has unrolled the loop and the operand is an OpConstant. This marks every `Offset`
// operand whose id is a constant (OpConstant, OpConstantComposite, OpConstantNull) of a
// non-gather image instruction as `ConstOffset` instead: the two share a position in the
// operand list, so only the mask word changes. Run it on optimised SPIR-V. Returns |spirv|
// unchanged when there is nothing to mark or it cannot be parsed.
std::vector<uint32_t> markConstantImageOffsets(const std::vector<uint32_t>& spirv);

}  // namespace varc::driver
