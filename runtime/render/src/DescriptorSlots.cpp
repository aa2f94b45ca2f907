// SPDX-License-Identifier: Apache-2.0
#include "varc/render/DescriptorSlots.h"

#include <algorithm>
#include <tuple>

namespace varc::render {

namespace {

std::optional<VkDescriptorType> descriptorType(pack::ResourceKind kind) {
    switch (kind) {
        case pack::ResourceKind::SampledImage:
            return VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
        case pack::ResourceKind::Sampler:
            return VK_DESCRIPTOR_TYPE_SAMPLER;
        case pack::ResourceKind::CombinedImageSampler:
            return VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
        case pack::ResourceKind::StorageBuffer:
            return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        default:
            return std::nullopt;
    }
}

// Adds |slot|, or merges it with an equal one already at its (set, binding).
Status addSlot(std::vector<DescriptorSlot>& slots, DescriptorSlot slot) {
    for (DescriptorSlot& existing : slots) {
        if (existing.set != slot.set || existing.binding != slot.binding) continue;
        if (existing.type != slot.type || existing.name != slot.name) {
            return makeError(ErrorCode::InvalidInput,
                             "set " + std::to_string(slot.set) + " binding " +
                                 std::to_string(slot.binding) + " is '" + existing.name +
                                 "' in one stage and '" + slot.name + "' in another");
        }
        existing.stages |= slot.stages;
        return Ok{};
    }
    slots.push_back(std::move(slot));
    return Ok{};
}

}  // namespace

Result<std::vector<DescriptorSlot>> collectDescriptorSlots(
    const std::vector<StageReflection>& stages) {
    std::vector<DescriptorSlot> slots;
    for (const StageReflection& stage : stages) {
        for (const pack::UniformBlock& block : stage.reflection->uniformBlocks) {
            DescriptorSlot slot{block.set,
                                block.binding,
                                VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER,
                                static_cast<VkShaderStageFlags>(stage.stage),
                                block.name,
                                block,
                                pack::ResourceDim::None};
            if (Status added = addSlot(slots, std::move(slot)); !added) return added.error();
        }
        for (const pack::ResourceBinding& resource : stage.reflection->resources) {
            std::optional<VkDescriptorType> type = descriptorType(resource.kind);
            if (!type || resource.arraySize != 1) {
                return makeError(ErrorCode::Unsupported,
                                 "resource '" + resource.name +
                                     "' has a kind or array size the runtime cannot bind");
            }
            DescriptorSlot slot{resource.set,  resource.binding,
                                *type,         static_cast<VkShaderStageFlags>(stage.stage),
                                resource.name, std::nullopt,
                                resource.dim};
            if (Status added = addSlot(slots, std::move(slot)); !added) return added.error();
        }
    }
    std::sort(slots.begin(), slots.end(), [](const DescriptorSlot& a, const DescriptorSlot& b) {
        return std::tie(a.set, a.binding) < std::tie(b.set, b.binding);
    });
    return slots;
}

uint32_t descriptorSetCount(const std::vector<DescriptorSlot>& slots) {
    uint32_t count = 0;
    for (const DescriptorSlot& slot : slots) count = std::max(count, slot.set + 1);
    return count;
}

}  // namespace varc::render
