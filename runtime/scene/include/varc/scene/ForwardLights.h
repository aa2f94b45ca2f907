// SPDX-License-Identifier: Apache-2.0
// ForwardLights: which lights of a scene draw where for one object in forward rendering (Unity's
// rules, docs/LIGHTING.md §9), and the SH
// coefficients of the lights that fall through to SH.
#pragma once

#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "varc/scene/Scene.h"

namespace varc::scene {

struct ForwardLightAssignment {
    int mainDirectional = -1;        // index into Scene::lights drawn in ForwardBase, or -1
    std::vector<int> addLights;      // pixel lights drawn one ForwardAdd pass each, in order
    std::vector<int> vertexLights;   // <= 4 point lights shaded per vertex (VERTEXLIGHT_ON)
    std::vector<int> shLights;       // the rest, folded into SH
};

// The world-space bounding sphere of |object| (centre = object origin, radius = the mesh's
// bounding radius times the largest absolute scale).
struct BoundingSphere {
    glm::vec3 centre{0.0f};
    float radius = 0.0f;
};
BoundingSphere worldBounds(const Object& object);

// Per object: lights that cannot reach the object's bounds are ignored (point/spot whose range
// sphere does not intersect the object's world bounding sphere); sort by importance (Important
// before Auto before NotImportant, then by brightness at the object: intensity x luminance x
// distance attenuation); the brightest directional light that is not NotImportant is the main
// light (always per-pixel, in the base pass) unless it has a cookie, in which case it goes to the
// add passes and the base pass has no main light; Important lights and directional lights with a
// cookie are always pixel lights; Auto lights fill up to pixelLightCount pixel lights (the main
// light counts); NotImportant lights and the rest: the first 4 point lights become vertex
// lights, everything else SH. docs/LIGHTING.md §9 has the details.
ForwardLightAssignment assignForwardLights(const Scene& scene, const Object& object);

// The brightness assignForwardLights sorts by: intensity x luminance(colour) (Rec. 709 weights)
// x 1/(1 + 25 d²/range²) for point and spot lights, d = distance from the light to |centre|.
float lightBrightnessAt(const Light& light, const glm::vec3& centre);

// The normalised 9-coefficient SH (sh[channel][i], LIGHTING.md §5) of flat |scene.ambient| plus
// the lights |shLights| seen from |object|'s centre.
std::array<std::array<float, 9>, 3> shCoefficients(const Scene& scene, const Object& object,
                                                   const std::vector<int>& shLights);

// Flat ambient plus |shLights| projected into 9x3 SH (LIGHTING.md §5), packed as Unity does into
// unity_SHAr/Ag/Ab/Br/Bg/Bb/C (SHADER_ABI.md §4.4): returns the 7 vec4 in that order.
std::array<glm::vec4, 7> packedSH(const Scene& scene, const Object& object,
                                  const std::vector<int>& shLights);

// ShadeSH9(n) with the packed coefficients (LIGHTING.md §5), n.w = 1; not clamped.
glm::vec3 shadeSH9(const std::array<glm::vec4, 7>& sh, const glm::vec3& n);

}  // namespace varc::scene
