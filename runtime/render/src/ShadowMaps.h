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

namespace varc::render {

// Appends the caster draws of every object whose shader has a ShadowCaster pass (variant
// |keyword|, e.g. SHADOWS_DEPTH), seen through |matrices| with |camera| as their camera layer,
// into |target|; |mirrored| views flip culling. Adds each variant's describe() to |drawn|.
Status appendCasterDraws(RendererBase& renderer, const scene::Scene& scene,
                         const scene::CameraMatrices& matrices, const ShaderValues& camera,
                         const std::string& keyword, bool mirrored,
                         const vulkan::RenderTarget& target, FrameStorage& storage,
                         std::vector<Draw>& draws, std::vector<std::string>& drawn);

// The sampler shadow maps and screen masks are read with: nearest, clamp to edge, no compare
// (SHADER_ABI.md §6).
Result<vulkan::UniqueHandle<VkSampler>> createShadowSampler(const vulkan::VulkanContext& context,
                                                            const std::string& name);

class ShadowMaps {
public:
    // Renders the map of every light that has shadows: a depth map per spot light
    // (SHADOWS_DEPTH), a depth cube map per point light (SHADOWS_CUBE), a cascaded depth atlas
    // per directional light (read by the screen-space collector, ScreenShadowMasks).
    // Objects whose shader has no ShadowCaster pass cast no shadow, as in Unity. Errors name
    // the light or the object. The caster variants drawn are added to |drawn| (describe()).
    Status render(RendererBase& renderer, const scene::Scene& scene,
                  std::vector<std::string>& drawn);

    // The shadow map of light |index| with its nearest, clamp-to-edge sampler (for a directional
    // light, its cascade atlas); nullopt when the light has none this frame.
    std::optional<TextureBinding> map(size_t light) const;
    // Whether light |index| has a directional cascade atlas this frame, and its setup.
    bool isDirectional(size_t light) const {
        return mRendered.count(light) && mMaps.at(light).type == scene::LightType::Directional;
    }
    const scene::DirectionalShadowSetup& directional(size_t light) const {
        return mMaps.at(light).directional;
    }

    // Adds the receiver uniforms of light |index| to |values|: unity_WorldToShadow,
    // _LightShadowData, unity_ShadowFadeCenterAndType, _ShadowMapTexture_TexelSize, for point
    // lights _LightProjectionParams, for directional lights the cascade splits and spheres
    // (nothing for a light without a map).
    void addReceiverValues(const scene::Scene& scene, size_t light, ShaderValues& values) const;

private:
    struct LightMap {
        scene::LightType type = scene::LightType::Spot;
        scene::ShadowCamera spot;
        scene::PointShadowCamera point;
        scene::DirectionalShadowSetup directional;
        std::optional<vulkan::RenderTarget> target;  // the map (spot) or each face in turn (point)
        std::optional<vulkan::DeviceImage> cube;  // point: the depth cube the faces are copied to
        bool sampledBefore = false;  // the target's depth is in DEPTH_STENCIL_READ_ONLY_OPTIMAL
    };
    Status prepare(RendererBase& renderer, uint32_t resolution, bool cube, LightMap& map);
    Status casterDraws(RendererBase& renderer, const scene::Scene& scene,
                       const scene::CameraMatrices& matrices, const ShaderValues& camera,
                       const std::string& keyword, bool mirrored,
                       const vulkan::RenderTarget& target, FrameStorage& storage,
                       std::vector<Draw>& draws) {
        return appendCasterDraws(renderer, scene, matrices, camera, keyword, mirrored, target,
                                 storage, draws, *mDrawn);
    }
    Status renderSpot(RendererBase& renderer, const scene::Scene& scene, size_t light,
                      LightMap& map);
    Status renderPoint(RendererBase& renderer, const scene::Scene& scene, size_t light,
                       LightMap& map);
    Status renderDirectional(RendererBase& renderer, const scene::Scene& scene, size_t light,
                             LightMap& map);
    // A part of the map and the caster draws that go there.
    struct DepthTile {
        VkViewport viewport;
        VkRect2D area;
        const std::vector<Draw>* draws;
    };
    Status drawDepthPass(RendererBase& renderer, LightMap& map,
                         const std::vector<DepthTile>& tiles);

    std::vector<std::string>* mDrawn = nullptr;  // during render()

    std::map<size_t, LightMap> mMaps;  // by light index; targets reused across frames
    std::map<size_t, bool> mRendered;  // lights with a map this frame
    vulkan::UniqueHandle<VkSampler> mNearest;
};

}  // namespace varc::render
