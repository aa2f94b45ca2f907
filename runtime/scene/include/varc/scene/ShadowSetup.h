// SPDX-License-Identifier: Apache-2.0
// ShadowSetup: how a shadowed light's shadow map is rendered and read, and the shadow uniforms
// the shaders see (SHADER_ABI.md §4.7): the runtime and the CPU reference take these same
// inputs, as they take the same camera matrices.
#pragma once

#include <array>

#include <glm/glm.hpp>

#include "varc/scene/CameraMatrices.h"
#include "varc/scene/Scene.h"

namespace varc::scene {

struct ShadowCamera {
    CameraMatrices matrices;  // the caster pass's camera: light position, looking along the light
    glm::mat4 worldToShadow{1.0f};  // unity_WorldToShadow[0]: world -> (u w, v w, depth w, w)
    glm::vec4 bias{0.0f};           // unity_LightShadowBias
    uint32_t resolution = 512;      // texels per side of the square map
};

// A spot light's shadow camera: a square perspective frustum with the cone's angle as its field
// of view, from light.shadowNearPlane to light.range. worldToShadow maps a world point to
// texture coordinates (u right, v down, row 0 at v = 0) and the map's depth, all times w.
// Bias (varc's mapping of the light inspector's units): x = shadowBias / 100 (added to clip z,
// so depth grows by x / w), z = shadowNormalBias / 20 metres along the normal at grazing light.
ShadowCamera spotShadowCamera(const Light& light);

// A point light's depth cube map (Vulkan's depth-cube path, as Unity renders SHADOWS_CUBE there):
// six square faces of `shadowResolution` texels, each a 90-degree perspective view from the
// light between shadowNearPlane and range, laid out so that sampling the cube with the direction
// r = p - lightPos (Vulkan's face selection and face coordinates) finds the texel that face's
// camera drew p into. Face i in Vulkan's layer order +X, -X, +Y, -Y, +Z, -Z.
struct PointShadowCamera {
    std::array<glm::mat4, 6> faceViewProjection{};  // world -> Vulkan clip of each face
    std::array<bool, 6> mirrored{};  // the face maps the world with the other handedness than a
                                     // camera does: back faces look like front faces there
    // _LightProjectionParams = (f/(n-f), n f/(n-f), depth bias in metres, 1): the receiver's
    // depth for a direction whose largest component is m is -x + y / (m - z).
    glm::vec4 projectionParams{0.0f};
    glm::vec4 bias{0.0f};           // unity_LightShadowBias for the casters: (0, 0, normal, 0)
    uint32_t resolution = 512;
};

// Bias (varc's mapping): the depth bias shadowBias / 10 metres is applied by the receiver
// (projectionParams.z, as Unity does for depth cube maps); the caster gets the normal offset
// shadowNormalBias / 20 metres only.
PointShadowCamera pointShadowCamera(const Light& light);

// A directional light's cascaded shadow map: `scene.shadowCascades` orthographic cameras along
// the light, each covering one slice of the view frustum between the camera's near plane and the
// shadow distance, drawn into one square atlas of `shadowResolution` texels (one cascade: all of
// it; two or four: 2 x 2 tiles of half the size, cascade i at tile (i % 2, i / 2)).
struct DirectionalShadowSetup {
    int cascades = 1;
    uint32_t resolution = 512;   // the atlas
    uint32_t tileSize = 512;     // one cascade's square
    std::array<glm::mat4, 4> viewProjection{};  // world -> Vulkan clip of each cascade camera
    std::array<glm::mat4, 4> worldToShadow{};   // unity_WorldToShadow: world -> atlas (u, v, depth)
    std::array<glm::uvec2, 4> tileOrigin{};     // texels
    glm::vec4 splitsNear{0.0f}, splitsFar{0.0f};  // _LightSplitsNear/Far: view depths
    std::array<glm::vec4, 4> splitSpheres{};      // unity_ShadowSplitSpheres: (centre, radius)
    glm::vec4 splitSqRadii{0.0f};                 // unity_ShadowSplitSqRadii
    glm::vec4 bias{0.0f};                         // unity_LightShadowBias for the casters
    bool stableFit = true;
};

// Close fit: each camera is the light-space bounding box of its frustum slice. Stable fit: a
// square around the slice's bounding sphere (centre = the mean of the slice's corners), moved in
// whole texels so the map does not shimmer. Depth: from `shadowDistance` before the slice
// towards the light (casters there throw shadows into it) to its far side. Bias as for spot
// lights (x = shadowBias / 100 in clip z, z = shadowNormalBias / 20 metres).
DirectionalShadowSetup directionalShadowSetup(const Scene& scene, const Light& light);

// _LightShadowData = (1 - strength, 0, 5 / D, -4) with D = scene.shadowDistance: shadows fade
// from 0.8 D to D of view depth (fade = saturate(depth z + w)).
glm::vec4 lightShadowData(const Light& light, const Scene& scene);

// unity_ShadowFadeCenterAndType = (camera position, 0): type 0 fades by view depth.
glm::vec4 shadowFadeCenterAndType(const Scene& scene);

}  // namespace varc::scene
