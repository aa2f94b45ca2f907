// SPDX-License-Identifier: Apache-2.0
// Texture: a sampled 2D, cube or 3D image uploaded from Images through a staging buffer.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string>

#include "varc/core/Result.h"
#include "varc/image/Image.h"
#include "varc/vulkan/DeviceImage.h"
#include "varc/vulkan/VulkanContext.h"

namespace varc::vulkan {

struct TextureOptions {
    bool srgb = false;     // 8-bit images: VK_FORMAT_R8G8B8A8_SRGB instead of _UNORM
    bool mipmaps = false;  // a full mip chain, generated with linear vkCmdBlitImage
    std::string name = "texture";
};

// 8-bit Images become R8G8B8A8_UNORM (or _SRGB) textures; float Images become
// R16G16B16A16_SFLOAT (rounded to nearest half), a format Vulkan requires to be filterable,
// unlike R32G32B32A32_SFLOAT. After creation the image is in SHADER_READ_ONLY_OPTIMAL.
class Texture {
public:
    // Errors: ErrorCode::InvalidInput for an empty image; ErrorCode::Unsupported when mipmaps
    // are asked for a format the device cannot blit; ErrorCode::VulkanError.
    static Result<Texture> create2D(VulkanContext& context, const image::Image& image,
                                    const TextureOptions& options = {});
    // |faces| in Vulkan's layer order +X, -X, +Y, -Y, +Z, -Z: six square images of one size and
    // pixel format (else ErrorCode::InvalidInput). The view is VK_IMAGE_VIEW_TYPE_CUBE.
    static Result<Texture> createCube(VulkanContext& context, std::span<const image::Image> faces,
                                      const TextureOptions& options = {});
    // |slices| (front to back, one size and pixel format, else ErrorCode::InvalidInput) as a
    // 3D texture; the view is VK_IMAGE_VIEW_TYPE_3D. No mipmaps.
    static Result<Texture> createVolume(VulkanContext& context,
                                        std::span<const image::Image> slices,
                                        const TextureOptions& options = {});

    VkImage image() const { return mImage.image.get(); }
    VkImageView view() const { return mImage.view.get(); }
    VkFormat format() const { return mFormat; }
    uint32_t width() const { return mWidth; }
    uint32_t height() const { return mHeight; }
    uint32_t mipLevels() const { return mMipLevels; }
    bool isCube() const { return mCube; }
    bool isVolume() const { return mVolume; }

private:
    enum class Shape { Flat, Cube, Volume };
    static Result<Texture> create(VulkanContext& context, std::span<const image::Image> layers,
                                  Shape shape, const TextureOptions& options);
    Status upload(VulkanContext& context, std::span<const image::Image> layers);
    void recordMipChain(VkCommandBuffer commands, VkFilter filter) const;

    DeviceImage mImage;
    VkFormat mFormat = VK_FORMAT_UNDEFINED;
    uint32_t mWidth = 0;
    uint32_t mHeight = 0;
    uint32_t mMipLevels = 1;
    bool mCube = false;
    bool mVolume = false;
};

}  // namespace varc::vulkan
