// SPDX-License-Identifier: Apache-2.0
// A Vulkan graphics pipeline for one pack variant, one resolved render state and one render
// pass: shader modules from the pack's SPIR-V, descriptor set layouts from its reflection,
// vertex input from its semantics (SHADER_ABI.md §1, §8).
#pragma once

#include <vector>

#include "varc/pack/PackRenderState.h"
#include "varc/reader/VariantView.h"
#include "varc/render/DescriptorSlots.h"
#include "varc/vulkan/UniqueHandle.h"
#include "varc/vulkan/VulkanContext.h"

namespace varc::render {

struct PipelineTarget {
    VkRenderPass renderPass = VK_NULL_HANDLE;  // any pass compatible with the target's formats
    bool hasStencil = true;
    uint32_t colorAttachments = 1;  // every attachment gets the pass's blend state and mask
};

class VariantPipeline {
public:
    // Errors name the variant (VariantView::describe()): a missing vertex or fragment program,
    // SPIR-V that fails to decompress, unsupported vertex inputs or descriptors, Vulkan failures.
    static Result<VariantPipeline> create(vulkan::VulkanContext& context,
                                          const reader::VariantView& variant,
                                          const pack::PackRenderState& resolvedState,
                                          const PipelineTarget& target,
                                          VkPipelineCache cache = VK_NULL_HANDLE);

    VkPipeline pipeline() const { return mPipeline.get(); }
    VkPipelineLayout layout() const { return mLayout.get(); }
    const std::vector<DescriptorSlot>& slots() const { return mSlots; }
    // One layout per set 0..setCount-1 (empty layouts fill gaps).
    const std::vector<vulkan::UniqueHandle<VkDescriptorSetLayout>>& setLayouts() const {
        return mSetLayouts;
    }
    const std::string& description() const { return mDescription; }

private:
    std::vector<DescriptorSlot> mSlots;
    std::vector<vulkan::UniqueHandle<VkDescriptorSetLayout>> mSetLayouts;
    vulkan::UniqueHandle<VkPipelineLayout> mLayout;
    vulkan::UniqueHandle<VkPipeline> mPipeline;
    std::string mDescription;
};

}  // namespace varc::render
