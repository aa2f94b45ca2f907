// SPDX-License-Identifier: Apache-2.0
// The built-in values of the deferred light pass (SHADER_ABI.md §4.8, §5) and of its full-screen
// quad. Pure CPU, like SceneValues.h.
#pragma once

#include <array>

#include "varc/render/ShaderValues.h"
#include "varc/scene/CameraMatrices.h"
#include "varc/scene/Scene.h"

namespace varc::render {

// UnityDeferredLight (_LightPos = (position, 1/range²), _LightDir = (forward, 0), _LightColor =
// (colour × intensity, intensity), _LightAsQuad = 1 for the full-screen quad and 0 for a light
// volume, unity_LightmapFade = 0), unity_WorldToLight with the deferred spot convention, and
// shadow uniforms that make an unshadowed light exact (_LightShadowData = 0,
// unity_ShadowFadeCenterAndType = 0).
ShaderValues deferredLightValues(const scene::Light& light, bool asQuad);

// UnityPerDraw of a light volume (LightVolume.h) placed by |objectToWorld|.
ShaderValues lightVolumeValues(const glm::mat4& objectToWorld);

// UnityPerDraw of the full-screen quad: unity_ObjectToWorld = inverse(unity_MatrixVP), so the
// quad's vertices (Vulkan NDC) clip to themselves through UnityObjectToClipPos.
ShaderValues fullScreenQuadValues(const scene::CameraMatrices& camera);

// One vertex of the full-screen quad: Vulkan NDC position (z slightly in front of the near plane
// so the quad passes ZTest LEqual everywhere), the camera-local (+z forward) point on the far
// plane through that corner (the light pass's ray, SHADER_ABI.md §4.8) and the screen uv.
struct QuadCorner {
    glm::vec3 position;
    glm::vec3 ray;
    glm::vec2 uv;
};
// Corners top-left, top-right, bottom-right, bottom-left (framebuffer rows grow downwards);
// draw them as triangles (0, 1, 2), (0, 2, 3), clockwise in framebuffer space = front facing.
std::array<QuadCorner, 4> fullScreenQuad(const scene::CameraMatrices& camera);

}  // namespace varc::render
