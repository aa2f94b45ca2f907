// SPDX-License-Identifier: Apache-2.0
// Texture: a sampled 2D, cube or 3D image uploaded from Images through a staging buffer.
#include "varc/vulkan/Texture.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <utility>
#include <vector>

#include "varc/vulkan/Buffer.h"
#include "varc/vulkan/CheckVk.h"

namespace varc::vulkan {

namespace {

VkFormatFeatureFlags optimalFeatures(const VulkanContext& context, VkFormat format) {
    VkFormatProperties properties{};
    vkGetPhysicalDeviceFormatProperties(context.physicalDevice(), format, &properties);
    return properties.optimalTilingFeatures;
}

// The texel bytes of |image| in the texture's format (8-bit as is, floats as halves).
std::vector<std::byte> texelBytes(const image::Image& image) {
    if (!image.isFloat()) {
        std::span<const std::byte> raw = std::as_bytes(image.bytes());
        return std::vector<std::byte>(raw.begin(), raw.end());
    }
    std::span<const float> floats = image.floats();
    std::vector<std::byte> bytes(floats.size() * 2);
    for (std::size_t i = 0; i < floats.size(); ++i) {
        uint16_t half = image::floatToHalf(floats[i]);
        std::memcpy(bytes.data() + i * 2, &half, 2);
    }
    return bytes;
}

Status checkLayers(std::span<const image::Image> layers, bool cube) {
    const image::Image& first = layers.front();
    if (first.width() == 0 || first.height() == 0) {
        return makeError(ErrorCode::InvalidInput, "cannot make a texture from an empty image");
    }
    if (cube && (layers.size() != 6 || first.width() != first.height())) {
        return makeError(ErrorCode::InvalidInput, "a cube texture needs six square faces");
    }
    for (const image::Image& layer : layers) {
        if (layer.width() != first.width() || layer.height() != first.height() ||
            layer.format() != first.format()) {
            return makeError(ErrorCode::InvalidInput, "the faces or slices differ in size or pixel format");
        }
    }
    return Ok{};
}

}  // namespace

Result<Texture> Texture::create2D(VulkanContext& context, const image::Image& image,
                                  const TextureOptions& options) {
    return create(context, std::span<const image::Image>(&image, 1), Shape::Flat, options);
}

Result<Texture> Texture::createCube(VulkanContext& context, std::span<const image::Image> faces,
                                    const TextureOptions& options) {
    if (faces.size() != 6) {
        return makeError(ErrorCode::InvalidInput,
                         "a cube texture needs six faces, got " + std::to_string(faces.size()));
    }
    return create(context, faces, Shape::Cube, options);
}

Result<Texture> Texture::createVolume(VulkanContext& context, std::span<const image::Image> slices,
                                      const TextureOptions& options) {
    if (slices.empty()) return makeError(ErrorCode::InvalidInput, "a 3D texture needs slices");
    if (options.mipmaps) {
        return makeError(ErrorCode::Unsupported, "3D textures are created without mipmaps");
    }
    return create(context, slices, Shape::Volume, options);
}

Result<Texture> Texture::create(VulkanContext& context, std::span<const image::Image> layers,
                                Shape shape, const TextureOptions& options) {
    bool cube = shape == Shape::Cube;
    if (Status status = checkLayers(layers, cube); !status) return status.error();
    Texture texture;
    const image::Image& first = layers.front();
    texture.mWidth = first.width();
    texture.mHeight = first.height();
    texture.mCube = cube;
    texture.mVolume = shape == Shape::Volume;
    texture.mFormat = first.isFloat() ? VK_FORMAT_R16G16B16A16_SFLOAT
                      : options.srgb  ? VK_FORMAT_R8G8B8A8_SRGB
                                      : VK_FORMAT_R8G8B8A8_UNORM;
    VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    if (options.mipmaps) {
        constexpr VkFormatFeatureFlags kBlit =
            VK_FORMAT_FEATURE_BLIT_SRC_BIT | VK_FORMAT_FEATURE_BLIT_DST_BIT;
        if ((optimalFeatures(context, texture.mFormat) & kBlit) != kBlit) {
            return makeError(ErrorCode::Unsupported,
                             "mipmaps need blits, which the device lacks for format " +
                                 std::to_string(texture.mFormat));
        }
        texture.mMipLevels =
            static_cast<uint32_t>(std::bit_width(std::max(texture.mWidth, texture.mHeight)));
        usage |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    }
    DeviceImageDesc desc;
    desc.format = texture.mFormat;
    desc.width = texture.mWidth;
    desc.height = texture.mHeight;
    desc.mipLevels = texture.mMipLevels;
    desc.cube = cube;
    desc.volume = texture.mVolume;
    desc.depth = static_cast<uint32_t>(layers.size());
    desc.usage = usage;
    Result<DeviceImage> image = createDeviceImage(context, desc, options.name);
    if (!image) return image.error();
    texture.mImage = std::move(*image);
    if (Status status = texture.upload(context, layers); !status) return status.error();
    return texture;
}

Status Texture::upload(VulkanContext& context, std::span<const image::Image> layers) {
    std::vector<std::byte> staged;
    std::vector<VkBufferImageCopy> regions;
    for (uint32_t layer = 0; layer < layers.size(); ++layer) {
        VkBufferImageCopy region{};
        region.bufferOffset = staged.size();
        // A volume's slices are depth offsets of its one layer; a cube's faces are layers.
        region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, mVolume ? 0 : layer, 1};
        region.imageOffset = {0, 0, mVolume ? static_cast<int32_t>(layer) : 0};
        region.imageExtent = {mWidth, mHeight, 1};
        regions.push_back(region);
        std::vector<std::byte> bytes = texelBytes(layers[layer]);
        staged.insert(staged.end(), bytes.begin(), bytes.end());
    }
    Result<Buffer> staging =
        Buffer::create(context, staged.size(), VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                       MemoryLocation::HostVisible, "texture staging");
    if (!staging) return staging.error();
    staging->write(staged);
    VkFilter filter =
        (optimalFeatures(context, mFormat) & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT)
            ? VK_FILTER_LINEAR
            : VK_FILTER_NEAREST;
    return context.submitAndWait([&](VkCommandBuffer commands) {
        transitionLayout(commands, image(), VK_IMAGE_ASPECT_COLOR_BIT,
                         {VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                          VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                          VK_ACCESS_TRANSFER_WRITE_BIT});
        vkCmdCopyBufferToImage(commands, staging->handle(), image(),
                               VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                               static_cast<uint32_t>(regions.size()), regions.data());
        recordMipChain(commands, filter);
    });
}

// Level i is blitted from level i - 1 once that level is complete; each finished level moves
// to SHADER_READ_ONLY_OPTIMAL. With one level this is just the final transition.
void Texture::recordMipChain(VkCommandBuffer commands, VkFilter filter) const {
    uint32_t layerCount = mCube ? 6 : 1;
    for (uint32_t level = 1; level < mMipLevels; ++level) {
        transitionLayout(
            commands, image(), VK_IMAGE_ASPECT_COLOR_BIT,
            {VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
             VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
             VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT, level - 1, 1});
        VkImageBlit blit{};
        blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level - 1, 0, layerCount};
        blit.srcOffsets[1] = {std::max(1, static_cast<int32_t>(mWidth >> (level - 1))),
                              std::max(1, static_cast<int32_t>(mHeight >> (level - 1))), 1};
        blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, level, 0, layerCount};
        blit.dstOffsets[1] = {std::max(1, static_cast<int32_t>(mWidth >> level)),
                              std::max(1, static_cast<int32_t>(mHeight >> level)), 1};
        vkCmdBlitImage(commands, image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image(),
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, filter);
        transitionLayout(
            commands, image(), VK_IMAGE_ASPECT_COLOR_BIT,
            {VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
             VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
             VK_ACCESS_SHADER_READ_BIT, level - 1, 1});
    }
    transitionLayout(
        commands, image(), VK_IMAGE_ASPECT_COLOR_BIT,
        {VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
         VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
         VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT, mMipLevels - 1, 1});
}

}  // namespace varc::vulkan
