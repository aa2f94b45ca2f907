// SPDX-License-Identifier: Apache-2.0
// LightTextures: CPU images of the built-in light textures (falloff table, default cookies) and
// the light-space matrices (SHADER_ABI.md §5, §6). No Vulkan.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "varc/scene/Scene.h"

namespace varc::scene {

constexpr uint32_t kFalloffTableSize = 1024;

// 1024 R16_UNORM texels, texel i = round(65535 · f((i + 0.5)/1024)).
std::vector<uint16_t> falloffTable();
// The analytic f(t) of LIGHTING.md §4: 1/(1 + 25t) · saturate((1 − t)/0.36).
float falloff(float t);
// The table sampled as the GPU does: linear filtering, clamp to edge, u = |t|.
float sampleFalloffTable(const std::vector<uint16_t>& table, float t);

// RGBA8 texels row-major (layer after layer). Sizes are documented in SHADER_ABI.md §6.
struct CookieImage {
    uint32_t width = 0, height = 0, layers = 1;
    std::vector<uint8_t> rgba;
};
CookieImage defaultSpotCookie();         // 128 x 128, soft disc in alpha
CookieImage defaultDirectionalCookie();  // 64 x 64, tiling pattern in alpha
CookieImage defaultPointCookie();        // 6 layers (+X, -X, +Y, -Y, +Z, -Z) of 32 x 32

// unity_WorldToLight of SHADER_ABI.md §5. |deferredSpotConvention| selects the deferred light
// pass's spot matrix instead of the forward (AutoLight) one. Identity for directional lights
// without cookie.
glm::mat4 worldToLight(const Light& light, bool deferredSpotConvention);

// Vulkan cube-map face selection (spec "Cube Map Face Selection"): for direction |d|, the face
// (0..5 = +X, -X, +Y, -Y, +Z, -Z) and the face coordinates (s, t) in [0, 1].
struct CubeCoord {
    int face = 0;
    glm::vec2 st{0.0f};
};
CubeCoord cubeFaceCoord(const glm::vec3& d);
// The inverse: the direction (not normalised) through face coordinates |st| of |face|.
glm::vec3 cubeFaceDirection(int face, const glm::vec2& st);

}  // namespace varc::scene
