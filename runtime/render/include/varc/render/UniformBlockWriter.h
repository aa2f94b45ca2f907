// SPDX-License-Identifier: Apache-2.0
// Lays named values out into a uniform block's bytes, by the block's reflection
// (docs/SHADER_ABI.md §1: every member is found by name; offsets and strides come from the pack).
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "varc/pack/ProgramReflection.h"
#include "varc/render/ShaderValues.h"

namespace varc::render {

// Where each member's value comes from: the first layer that has the name wins, so pass the
// most specific first (object, light, material, camera, frame).
using ValueLayers = std::span<const ShaderValues* const>;

struct BlockWriteReport {
    std::vector<std::string> missing;  // members no layer named (left zero)
};

// Fills |bytes| (resized to block.size, zeroed) member by member: scalars and vectors take the
// value's leading floats; int/uint/bool members take them converted; matrices take the columns
// of the value's 4x4 matrix (glm order), truncated to the member's shape; arrays take one
// value element per array element, up to the shorter of the two.
BlockWriteReport writeUniformBlock(const pack::UniformBlock& block, ValueLayers layers,
                                   std::vector<std::byte>& bytes);

}  // namespace varc::render
