// SPDX-License-Identifier: Apache-2.0
// CameraTargetCache: the camera key and the single colour target of the forward renderers.
#include "CameraTargetCache.h"

namespace varc::runtime {

CameraTargetKey cameraTargetKey(const scene::Camera& camera) {
    const glm::vec4& b = camera.background;
    return {camera.width, camera.height, camera.hdr, {b.r, b.g, b.b, b.a}};
}

Result<RenderTarget> createCameraTarget(VulkanContext& context, const scene::Camera& camera,
                                        std::string name) {
    RenderTargetDesc desc;
    desc.width = camera.width;
    desc.height = camera.height;
    desc.color = camera.hdr ? ColorFormat::Rgba16Float : ColorFormat::Rgba8Unorm;
    desc.clearColor = cameraTargetKey(camera).background;
    desc.name = std::move(name);
    return RenderTarget::create(context, desc);
}

}  // namespace varc::runtime
