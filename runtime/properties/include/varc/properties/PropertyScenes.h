// SPDX-License-Identifier: Apache-2.0
// PropertyScenes: the scenes the property checks draw for one lighting shader: a sphere, a cube
// and a plane with the shader's Properties defaults, black ambient, and the lights of each type
// the shader's ForwardAdd pass accepts (docs/PROPERTIES.md has the layout).
#pragma once

#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "varc/reader/ShaderView.h"
#include "varc/scene/Scene.h"

namespace varc::properties {

// Which lights a shader's forward passes can draw, from its ForwardAdd pass's keywords: POINT,
// SPOT, DIRECTIONAL_COOKIE, POINT_COOKIE (multi_compile_fwdadd). A ForwardAdd pass without any
// light keyword (it tells lights apart by _WorldSpaceLightPos0.w) takes directional and point
// lights only.
struct LightSupport {
    bool forwardBase = false;  // the shader has a ForwardBase pass: it is checked at all
    bool forwardAdd = false;   // ... and a ForwardAdd pass: extra pixel lights
    bool deferred = false;     // ... and a Deferred (G-buffer) pass: forward_deferred applies
    bool point = false;
    bool spot = false;
    bool directionalCookie = false;
    bool pointCookie = false;
};
LightSupport lightSupportOf(const reader::ShaderView& shader);

// An |size| x |size| scene of |shader| (materials keep the pack's Properties defaults): a
// sphere, a cube and a plane under them, camera above and in front, black background and
// ambient, no lights; |hdr| picks the RGBA16F target (else RGBA8 UNORM).
scene::Scene emptyScene(const std::string& shader, bool hdr, uint32_t size);

// |scene| with |lights| added.
scene::Scene withLights(scene::Scene scene, const std::vector<scene::Light>& lights);

// The lights of the checks. The key lights all reach the objects: a directional light (the
// main light of the base pass), a second directional light, a point light and a spot light
// (both Important, so each draws in its own ForwardAdd pass).
scene::Light keyDirectional();
scene::Light secondDirectional();
scene::Light keyPoint();
scene::Light keySpot();
// A point (or spot) light above the cube whose range sphere reaches the cube's and the plane's
// bounding spheres (so forward rendering draws it on them) but no surface point: a correct
// shader attenuates it to the falloff table's last texel (LightTextures.h, ~5e-5).
scene::Light outOfRangePoint();
scene::Light outOfRangeSpot();

// |scene| moved by the similarity p -> scale x p + offset: camera, objects and lights moved, the
// objects' scales, the lights' ranges, directional cookie sizes and the camera's clip planes
// multiplied by |scale|. A correct lighting shader draws the same image.
scene::Scene similar(const scene::Scene& scene, float scale, glm::vec3 offset);

// |scene| turned by |degrees| about the world y axis through the origin: camera, objects and
// lights (positions turned, Unity Euler y angles increased: Ry(a) Ry(y) Rx(x) Rz(z) =
// Ry(a + y) Rx(x) Rz(z)). The camera turns too, so a correct shader draws the same image.
scene::Scene turned(const scene::Scene& scene, float degrees);

// |scene| mirrored in the plane x = 0 (S = diag(-1, 1, 1)): positions' x negated, Unity Euler
// angles (x, y, z) -> (x, -y, -z) (S Ry(y) Rx(x) Rz(z) S = Ry(-y) Rx(x) Rz(-z)) and objects'
// x scale negated, so each object is its original mirrored vertex by vertex (a transform with a
// negative determinant, which culls the other side, as in Unity). The camera of emptyScene()
// lies in that plane looking along it: a correct shader draws the render of |scene| flipped left
// to right.
scene::Scene mirrored(const scene::Scene& scene);

// A directional light shining straight down the y axis.
scene::Light overheadDirectional();

// |light| (a point or spot light) moved onto the y axis at height |height|; a spot keeps its
// direction (keySpot() points straight down).
scene::Light onLightAxis(scene::Light light, float height);

// |scene| seen from straight above: the camera at (0, 6.5, 0) looking down the y axis at the
// origin (image right = world +x, image up = world +z).
scene::Scene fromAbove(scene::Scene scene);

// |scene| with its objects (not the camera or the lights) turned by |degrees| about the world y
// axis through the origin. Seen fromAbove() with lights on that axis (overheadDirectional(),
// onLightAxis()), a correct shader draws the image turned by |degrees| (clockwise on screen).
scene::Scene objectsTurned(const scene::Scene& scene, float degrees);

// The floor of emptyScene() alone (the sphere and cube removed), seen fromAbove(): every pixel
// that draws it shows its top face, whose normal is +y.
scene::Scene floorFromAbove(const std::string& shader, uint32_t size);

// |light| moved under that floor, shining up at its bottom face: a directional light pointing
// straight up; a point or spot light 5.5 m below the floor's centre (a spot pointing up), with a
// range of 12 m, so the direction to it from every point of the top face has y < -0.96.
scene::Light underFloor(scene::Light light);

}  // namespace varc::properties
