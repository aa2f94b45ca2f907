// SPDX-License-Identifier: Apache-2.0
// Per-frame uniform memory and descriptor sets: each draw gets its uniform blocks written by name
// (UniformBlockWriter) into one host-visible buffer and its textures bound by name.
#pragma once

#include <functional>
#include <optional>
#include <string_view>

#include "varc/render/UniformBlockWriter.h"
#include "varc/render/VariantPipeline.h"
#include "varc/vulkan/Buffer.h"

namespace varc::render {

struct TextureBinding {
    VkImageView view = VK_NULL_HANDLE;
    VkSampler sampler = VK_NULL_HANDLE;
    // The layout the image is in while the draw executes (a sampled depth buffer that is also the
    // pass's read-only depth attachment: VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL).
    VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
};
// The texture bound for a resource name and dimension; nullopt = the runtime has none (error).
using TextureLookup =
    std::function<std::optional<TextureBinding>(std::string_view name, pack::ResourceDim dim)>;

class DrawResources {
public:
    // |uniformBytes| of uniform memory and room for |maxSets| descriptor sets per frame.
    static Result<DrawResources> create(vulkan::VulkanContext& context,
                                        VkDeviceSize uniformBytes = 8u << 20,
                                        uint32_t maxSets = 4096);

    // Writes |pipeline|'s uniform blocks from |layers| and its textures from |textures|, then
    // binds its descriptor sets on |commands|. Errors: out of frame memory or sets (the message
    // says which), a texture nobody provides. |missing| (optional) collects members left zero.
    Status bind(VkCommandBuffer commands, const VariantPipeline& pipeline, ValueLayers layers,
                const TextureLookup& textures, std::vector<std::string>* missing = nullptr);

    // Recycles all memory and sets; call when the frame's commands have finished executing.
    Status reset();

private:
    Result<VkDeviceSize> writeBlock(const std::vector<std::byte>& bytes);

    vulkan::VulkanContext* mContext = nullptr;
    vulkan::Buffer mUniforms;
    VkDeviceSize mUsed = 0;
    VkDeviceSize mAlignment = 256;
    vulkan::UniqueHandle<VkDescriptorPool> mPool;
};

}  // namespace varc::render
