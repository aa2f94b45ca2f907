// SPDX-License-Identifier: Apache-2.0
#include "varc/render/DrawResources.h"

#include <array>
#include <cstring>

#include "varc/vulkan/CheckVk.h"

namespace varc::render {

Result<DrawResources> DrawResources::create(vulkan::VulkanContext& context,
                                            VkDeviceSize uniformBytes, uint32_t maxSets) {
    DrawResources resources;
    resources.mContext = &context;
    resources.mAlignment =
        std::max<VkDeviceSize>(context.properties().limits.minUniformBufferOffsetAlignment, 16);
    auto buffer = vulkan::Buffer::create(context, uniformBytes, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT,
                                         vulkan::MemoryLocation::HostVisible, "frame uniforms");
    if (!buffer) return buffer.error();
    resources.mUniforms = std::move(*buffer);
    std::array<VkDescriptorPoolSize, 4> sizes = {
        {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, maxSets * 8},
         {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, maxSets * 8},
         {VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, maxSets * 4},
         {VK_DESCRIPTOR_TYPE_SAMPLER, maxSets * 4}}};
    VkDescriptorPoolCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
    info.maxSets = maxSets;
    info.poolSizeCount = static_cast<uint32_t>(sizes.size());
    info.pPoolSizes = sizes.data();
    VkDescriptorPool pool = VK_NULL_HANDLE;
    if (Status ok = vulkan::checkVk(vkCreateDescriptorPool(context.device(), &info, nullptr, &pool),
                                    "vkCreateDescriptorPool");
        !ok) {
        return ok.error();
    }
    resources.mPool = vulkan::UniqueHandle<VkDescriptorPool>(context.device(), pool);
    return resources;
}

Result<VkDeviceSize> DrawResources::writeBlock(const std::vector<std::byte>& bytes) {
    VkDeviceSize offset = (mUsed + mAlignment - 1) / mAlignment * mAlignment;
    if (offset + bytes.size() > mUniforms.size()) {
        return makeError(ErrorCode::Unsupported, "frame uniform memory exhausted (" +
                                                     std::to_string(mUniforms.size()) +
                                                     " bytes); draw fewer objects per frame");
    }
    mUniforms.write(bytes, offset);
    mUsed = offset + bytes.size();
    return offset;
}

Status DrawResources::bind(VkCommandBuffer commands, const VariantPipeline& pipeline,
                           ValueLayers layers, const TextureLookup& textures,
                           std::vector<std::string>* missing) {
    const auto& setLayouts = pipeline.setLayouts();
    if (setLayouts.empty()) return Ok{};
    std::vector<VkDescriptorSetLayout> rawLayouts;
    for (const auto& layout : setLayouts) rawLayouts.push_back(layout.get());
    std::vector<VkDescriptorSet> sets(rawLayouts.size());
    VkDescriptorSetAllocateInfo allocate{};
    allocate.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
    allocate.descriptorPool = mPool.get();
    allocate.descriptorSetCount = static_cast<uint32_t>(rawLayouts.size());
    allocate.pSetLayouts = rawLayouts.data();
    if (Status ok =
            vulkan::checkVk(vkAllocateDescriptorSets(mContext->device(), &allocate, sets.data()),
                            "vkAllocateDescriptorSets (frame descriptor pool exhausted?)");
        !ok) {
        return ok;
    }
    const std::vector<DescriptorSlot>& slots = pipeline.slots();
    std::vector<VkDescriptorBufferInfo> bufferInfos(slots.size());
    std::vector<VkDescriptorImageInfo> imageInfos(slots.size());
    std::vector<VkWriteDescriptorSet> writes;
    std::vector<std::byte> bytes;
    for (size_t i = 0; i < slots.size(); ++i) {
        const DescriptorSlot& slot = slots[i];
        VkWriteDescriptorSet write{};
        write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        write.dstSet = sets[slot.set];
        write.dstBinding = slot.binding;
        write.descriptorCount = 1;
        write.descriptorType = slot.type;
        if (slot.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER) {
            BlockWriteReport report = writeUniformBlock(*slot.block, layers, bytes);
            if (missing)
                missing->insert(missing->end(), report.missing.begin(), report.missing.end());
            auto offset = writeBlock(bytes);
            if (!offset) return offset.error();
            bufferInfos[i] = {mUniforms.handle(), *offset,
                              std::max<VkDeviceSize>(bytes.size(), 16)};
            write.pBufferInfo = &bufferInfos[i];
        } else if (slot.type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER) {
            return makeError(ErrorCode::Unsupported,
                             pipeline.description() + ": storage buffer '" + slot.name +
                                 "' cannot be bound by the forward renderer");
        } else {
            std::optional<TextureBinding> texture =
                textures ? textures(slot.name, slot.dim) : std::nullopt;
            if (!texture) {
                return makeError(ErrorCode::NotFound,
                                 pipeline.description() + ": no texture for '" + slot.name + "'");
            }
            imageInfos[i] = {texture->sampler, texture->view, texture->layout};
            write.pImageInfo = &imageInfos[i];
        }
        writes.push_back(write);
    }
    vkUpdateDescriptorSets(mContext->device(), static_cast<uint32_t>(writes.size()), writes.data(),
                           0, nullptr);
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline.layout(), 0,
                            static_cast<uint32_t>(sets.size()), sets.data(), 0, nullptr);
    return Ok{};
}

Status DrawResources::reset() {
    mUsed = 0;
    return vulkan::checkVk(vkResetDescriptorPool(mContext->device(), mPool.get(), 0),
                           "vkResetDescriptorPool");
}

}  // namespace varc::render
