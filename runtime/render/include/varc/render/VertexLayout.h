// SPDX-License-Identifier: Apache-2.0
// The one interleaved vertex format the runtime's meshes use, and how a program's reflected
// vertex inputs (HLSL semantics, or GLSL legacy names) map onto it (SHADER_ABI.md §8).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

#include "varc/core/Result.h"
#include "varc/pack/ProgramReflection.h"

namespace varc::render {

// Interleaved, 64 bytes per vertex.
struct MeshVertex {
    float position[3];
    float normal[3];
    float tangent[4];  // xyz, w = ±1 handedness
    float uv[2];
    float color[4];
};
static_assert(sizeof(MeshVertex) == 64);

struct VertexInputLayout {
    VkVertexInputBindingDescription binding{};
    std::vector<VkVertexInputAttributeDescription> attributes;
};

// One attribute per reflected input, at its reflected location. POSITION (w filled with 1 by
// Vulkan), NORMAL, TANGENT, TEXCOORDn (all read uv0) and COLOR; GLSL varc_Vertex, varc_Normal,
// varc_Color, varc_MultiTexCoordN. InvalidInput naming the input for anything else.
Result<VertexInputLayout> vertexInputLayout(const std::vector<pack::VertexInput>& inputs);

}  // namespace varc::render
