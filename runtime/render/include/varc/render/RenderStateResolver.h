// SPDX-License-Identifier: Apache-2.0
// A pass's render state with its property references (`Blend [_SrcBlend] [_DstBlend]`) resolved
// against a material, and its translation to Vulkan pipeline state.
#pragma once

#include <vulkan/vulkan.h>

#include <glm/glm.hpp>

#include "varc/pack/PackRenderState.h"
#include "varc/render/ShaderValues.h"

namespace varc::render {

// Every StateField's property replaced by the material's float value (Unity's enum numbers, as
// `Blend [_SrcBlend]` expects); fields whose property the material lacks keep their default.
// The result has no property names left, so it compares and hashes as plain values.
pack::PackRenderState resolveRenderState(const pack::PackRenderState& state,
                                         const ShaderValues& material);

// |state| for an object placed by |objectToWorld|: a mirroring transform (negative determinant)
// turns its triangles over on screen, so Cull Back becomes Cull Front and the reverse, as Unity
// does for negatively scaled objects.
pack::PackRenderState forObjectTransform(pack::PackRenderState state,
                                         const glm::mat4& objectToWorld);

// The Vulkan pieces of a resolved state. Culling uses VK_FRONT_FACE_CLOCKWISE: Unity's meshes
// are clockwise from outside and varc's projection flips y (SHADER_ABI.md §2).
struct VulkanRenderState {
    VkPipelineRasterizationStateCreateInfo rasterization{};
    VkPipelineDepthStencilStateCreateInfo depthStencil{};
    VkPipelineColorBlendAttachmentState blend{};
};
VulkanRenderState toVulkan(const pack::PackRenderState& resolved, bool hasStencil);

}  // namespace varc::render
