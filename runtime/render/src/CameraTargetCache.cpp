// SPDX-License-Identifier: Apache-2.0
// CameraTargetCache: the camera key and the single colour target of the forward renderers.
#include "CameraTargetCache.h"

namespace varc::render {

CameraTargetKey cameraTargetKey(const scene::Camera& camera) {
    const glm::vec4& b = camera.background;
    return {camera.width, camera.height, camera.hdr, {b.r, b.g, b.b, b.a}};
}

Result<vulkan::RenderTarget> createCameraTarget(vulkan::VulkanContext& context,
                                                const scene::Camera& camera, std::string name) {
    vulkan::RenderTargetDesc desc;
    desc.width = camera.width;
    desc.height = camera.height;
    desc.color = camera.hdr ? vulkan::ColorFormat::Rgba16Float : vulkan::ColorFormat::Rgba8Unorm;
    desc.clearColor = cameraTargetKey(camera).background;
    desc.name = std::move(name);
    return vulkan::RenderTarget::create(context, desc);
}

}  // namespace varc::render
