// SPDX-License-Identifier: Apache-2.0
// The descriptors a variant's stage programs declare, merged into one pipeline-layout plan.
#pragma once

#include <vulkan/vulkan.h>

#include <optional>
#include <string>
#include <vector>

#include "varc/core/Result.h"
#include "varc/pack/ProgramReflection.h"

namespace varc::render {

struct DescriptorSlot {
    uint32_t set = 0;
    uint32_t binding = 0;
    VkDescriptorType type = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    VkShaderStageFlags stages = 0;
    std::string name;                                 // block or resource name
    std::optional<pack::UniformBlock> block;          // uniform buffers: the layout to fill
    pack::ResourceDim dim = pack::ResourceDim::None;  // textures: 2D, Cube, ...
};

struct StageReflection {
    VkShaderStageFlagBits stage = VK_SHADER_STAGE_VERTEX_BIT;
    const pack::ProgramReflection* reflection = nullptr;
};

// Slots sorted by (set, binding). A (set, binding) used by two stages must name the same thing
// (it then gets both stage bits); otherwise InvalidInput. Storage images, texel buffers and
// input attachments are Unsupported (the forward and deferred techniques never use them).
Result<std::vector<DescriptorSlot>> collectDescriptorSlots(
    const std::vector<StageReflection>& stages);

// 1 + the highest set number used; 0 when there are no descriptors.
uint32_t descriptorSetCount(const std::vector<DescriptorSlot>& slots);

}  // namespace varc::render
