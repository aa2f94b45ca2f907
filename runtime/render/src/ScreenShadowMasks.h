// SPDX-License-Identifier: Apache-2.0
// ScreenShadowMasks: the screen-space shadow masks of a scene's shadowed directional lights, as
// Unity's built-in pipeline makes them: the camera's depth drawn with the objects' ShadowCaster
// passes, then the collector shader (Hidden/varc/ScreenSpaceShadows) turns depth and the light's
// cascade atlas into a mask the lit passes read as `_ShadowMapTexture` (SHADOWS_SCREEN).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "Draw.h"
#include "GpuMesh.h"
#include "RendererBase.h"
#include "ShadowMaps.h"
#include "varc/vulkan/RenderTarget.h"

namespace varc::render {

inline constexpr const char* kScreenShadowShader = "Hidden/varc/ScreenSpaceShadows";

class ScreenShadowMasks {
public:
    // One mask per directional light with a cascade atlas in |shadows|. Errors: the collector
    // shader in no pack, a render error (naming the object or the light). The depth prepass's
    // and the collector's variants are added to |drawn|.
    Status render(RendererBase& renderer, const scene::Scene& scene, const ShadowMaps& shadows,
                  const scene::CameraMatrices& matrices, std::vector<std::string>& drawn);

    // The mask of light |index| (Rgba32Float, .r = shadow, nearest, clamp); nullopt without.
    std::optional<TextureBinding> mask(size_t light) const;

private:
    // The command recording of render(): the depth pass, then the masks.
    Status recordMasks(VkCommandBuffer commands, RendererBase& renderer,
                       const std::vector<Draw>& depthDraws,
                       const std::map<size_t, Draw>& collectorDraws, uint32_t& drawCount);
    Status prepare(RendererBase& renderer, const scene::Camera& camera,
                   const std::vector<size_t>& lights);

    std::optional<vulkan::RenderTarget> mDepth;     // the camera depth texture
    std::map<size_t, vulkan::RenderTarget> mMasks;  // by light index
    bool mSampledBefore = false;              // targets are in their sampled layouts
    std::map<size_t, bool> mRendered;         // lights with a mask this frame
    vulkan::UniqueHandle<VkSampler> mNearest;
};

}  // namespace varc::render
