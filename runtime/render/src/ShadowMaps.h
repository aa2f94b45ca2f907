// SPDX-License-Identifier: Apache-2.0
// ShadowMaps: the depth maps of a scene's shadowed lights, rendered with each object's
// ShadowCaster pass before the lit passes read them (SHADER_ABI.md §4.7, LIGHTING.md §6).
#pragma once

#include <map>
#include <optional>

#include "RendererBase.h"
#include "varc/render/ShaderValues.h"
#include "varc/scene/ShadowSetup.h"
#include "varc/vulkan/RenderTarget.h"

namespace varc::runtime {

class ShadowMaps {
public:
    // Renders the map of every light that has shadows and a type varc renders shadows for
    // (spot lights: one depth map each). Objects whose shader has no ShadowCaster pass cast no
    // shadow, as in Unity. Errors name the light or the object.
    Status render(RendererBase& renderer, const scene::Scene& scene);

    // The shadow map of light |index| with its nearest, clamp-to-edge sampler; nullopt when the
    // light has none this frame.
    std::optional<TextureBinding> map(size_t light) const;

    // Adds the receiver uniforms of light |index| to |values|: unity_WorldToShadow,
    // _LightShadowData, unity_ShadowFadeCenterAndType, _ShadowMapTexture_TexelSize (nothing for a
    // light without a map).
    void addReceiverValues(const scene::Scene& scene, size_t light, ShaderValues& values) const;

private:
    struct LightMap {
        scene::ShadowCamera camera;
        std::optional<RenderTarget> target;
        bool sampledBefore = false;  // the depth is in DEPTH_STENCIL_READ_ONLY_OPTIMAL
    };
    Status renderSpot(RendererBase& renderer, const scene::Scene& scene, size_t light,
                      LightMap& map);

    std::map<size_t, LightMap> mMaps;  // by light index; targets reused across frames
    std::map<size_t, bool> mRendered;  // lights with a map this frame
    UniqueHandle<VkSampler> mNearest;
};

}  // namespace varc::runtime
