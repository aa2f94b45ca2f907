// SPDX-License-Identifier: Apache-2.0
// ShadowMaps: the depth maps of a scene's shadowed lights, rendered with each object's
// ShadowCaster pass before the lit passes read them (SHADER_ABI.md §4.7, LIGHTING.md §6).
#pragma once

#include <map>
#include <optional>
#include <vector>

#include "Draw.h"
#include "RendererBase.h"
#include "varc/render/ShaderValues.h"
#include "varc/scene/ShadowSetup.h"
#include "varc/vulkan/DeviceImage.h"
#include "varc/vulkan/RenderTarget.h"

namespace varc::runtime {

class ShadowMaps {
public:
    // Renders the map of every light that has shadows and a type varc renders shadows for: a
    // depth map per spot light (SHADOWS_DEPTH), a depth cube map per point light (SHADOWS_CUBE).
    // Objects whose shader has no ShadowCaster pass cast no shadow, as in Unity. Errors name
    // the light or the object. The caster variants drawn are added to |drawn| (describe()).
    Status render(RendererBase& renderer, const scene::Scene& scene,
                  std::vector<std::string>& drawn);

    // The shadow map of light |index| with its nearest, clamp-to-edge sampler; nullopt when the
    // light has none this frame.
    std::optional<TextureBinding> map(size_t light) const;

    // Adds the receiver uniforms of light |index| to |values|: unity_WorldToShadow,
    // _LightShadowData, unity_ShadowFadeCenterAndType, _ShadowMapTexture_TexelSize and, for
    // point lights, _LightProjectionParams (nothing for a light without a map).
    void addReceiverValues(const scene::Scene& scene, size_t light, ShaderValues& values) const;

private:
    struct LightMap {
        scene::LightType type = scene::LightType::Spot;
        scene::ShadowCamera spot;
        scene::PointShadowCamera point;
        std::optional<RenderTarget> target;  // the map (spot) or each face in turn (point)
        std::optional<DeviceImage> cube;     // point: the depth cube the faces are copied to
        bool sampledBefore = false;  // the target's depth is in DEPTH_STENCIL_READ_ONLY_OPTIMAL
    };
    Status prepare(RendererBase& renderer, uint32_t resolution, bool cube, LightMap& map);
    // The caster draws of every object whose shader has a ShadowCaster pass, seen through
    // |matrices| with |camera| as their camera layer.
    Status casterDraws(RendererBase& renderer, const scene::Scene& scene,
                       const scene::CameraMatrices& matrices, const ShaderValues& camera,
                       const std::string& keyword, bool mirrored, const RenderTarget& target,
                       FrameStorage& storage, std::vector<Draw>& draws);
    Status renderSpot(RendererBase& renderer, const scene::Scene& scene, size_t light,
                      LightMap& map);
    Status renderPoint(RendererBase& renderer, const scene::Scene& scene, size_t light,
                       LightMap& map);

    std::vector<std::string>* mDrawn = nullptr;  // during render()

    std::map<size_t, LightMap> mMaps;  // by light index; targets reused across frames
    std::map<size_t, bool> mRendered;  // lights with a map this frame
    UniqueHandle<VkSampler> mNearest;
};

}  // namespace varc::runtime
