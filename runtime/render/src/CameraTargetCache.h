// SPDX-License-Identifier: Apache-2.0
// CameraTargetCache: the render targets a renderer has made so far, one per camera size, HDR mode
// and background colour, each made on first use and kept for later frames.
#pragma once

#include <array>
#include <compare>
#include <cstdint>
#include <map>
#include <string>
#include <utility>

#include "varc/core/Result.h"
#include "varc/scene/Scene.h"
#include "varc/vulkan/RenderTarget.h"

namespace varc::render {

// What of a camera a target depends on: two cameras with equal keys can share a target.
struct CameraTargetKey {
    uint32_t width = 0, height = 0;
    bool hdr = false;
    std::array<float, 4> background{};  // the clear colour, linear RGBA
    auto operator<=>(const CameraTargetKey&) const = default;
};

CameraTargetKey cameraTargetKey(const scene::Camera& camera);

template <typename Target>
class CameraTargetCache {
public:
    // The target for |camera|: the cached one, or |create(camera)| (returning Result<Target>)
    // on first use. Errors: those of |create|; nothing is cached then, so the next call retries.
    template <typename Create>
    Result<const Target*> get(const scene::Camera& camera, Create&& create) {
        CameraTargetKey key = cameraTargetKey(camera);
        auto it = mTargets.find(key);
        if (it == mTargets.end()) {
            Result<Target> created = std::forward<Create>(create)(camera);
            if (!created) return created.error();
            it = mTargets.emplace(key, std::move(*created)).first;
        }
        return &it->second;
    }

private:
    std::map<CameraTargetKey, Target> mTargets;
};

// A colour + depth/stencil target of |camera|'s size (HDR: Rgba16Float, else Rgba8Unorm) that
// clears to its background, its Vulkan objects named after |name|. Errors: those of
// RenderTarget::create.
Result<vulkan::RenderTarget> createCameraTarget(vulkan::VulkanContext& context,
                                                const scene::Camera& camera, std::string name);

}  // namespace varc::render
