// SPDX-License-Identifier: Apache-2.0
// Rasterizer: a CPU triangle rasteriser with Vulkan's rules (pixel centres at +0.5, top-left
// fill rule on an 8-bit sub-pixel grid, near/far clipping, back-face culling with clockwise front
// faces in y-down framebuffer space, depth test LessEqual) and the per-pixel classification the
// comparator uses. No Vulkan.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <vector>

#include "varc/scene/CameraMatrices.h"
#include "varc/scene/Scene.h"

namespace varc::reference {

// Back: drop back faces (counter-clockwise on screen); Front: drop front faces, what a back-face
// cull becomes for an object mirrored by a negative-determinant transform (Unity flips it).
enum class CullMode { None, Back, Front };

// One covered pixel centre: framebuffer pixel (x, y), depth z/w in [0, 1], and the
// perspective-correct barycentric weights of the triangle's three ORIGINAL vertices (sum 1).
struct Fragment {
    uint32_t x = 0, y = 0;
    float depth = 0.0f;
    glm::vec3 bary{0.0f};
};
using FragmentFn = std::function<void(const Fragment&)>;

// Rasterises the triangle with clip-space vertices |clip| (Vulkan clip space: x, y in [-w, w],
// y down, z in [0, w]) into a |width| x |height| framebuffer. The triangle is clipped against
// 0 <= z <= w; with CullMode::Back, triangles whose framebuffer area is not clockwise (Vulkan
// VK_FRONT_FACE_CLOCKWISE) are dropped. Calls |emit| once per covered pixel centre. A triangle
// with a vertex that is not finite (NaN or infinity) draws nothing.
void rasterizeTriangle(const std::array<glm::vec4, 3>& clip, uint32_t width, uint32_t height,
                       CullMode cull, const FragmentFn& emit);

// The nearest surface per pixel after drawing every object of a scene in order with depth test
// LessEqual (depth cleared to 1).
struct SurfaceSample {
    int object = -1;  // index into Scene::objects, -1 = background
    uint32_t triangle = 0;
    glm::vec3 bary{0.0f};
    float depth = 1.0f;
};
struct VisibilityBuffer {
    uint32_t width = 0, height = 0;
    std::vector<SurfaceSample> samples;  // row-major, row 0 at the top
    const SurfaceSample& at(uint32_t x, uint32_t y) const { return samples[size_t{y} * width + x]; }
};
// Objects whose |drawn| entry is false are left out (an empty |drawn| draws every object).
VisibilityBuffer rasterizeScene(const scene::Scene& scene, const scene::CameraMatrices& camera,
                                const std::vector<bool>& drawn = {});

// Background: no triangle covers the pixel centre and none covers a neighbour's; Edge: within one
// pixel of a silhouette, an object boundary or a crease (two neighbouring pixels of one object
// in different Mesh::smoothGroups, e.g. on two faces of a cube); Interior: everything else.
enum class PixelClass : uint8_t { Background, Edge, Interior };
struct Classification {
    uint32_t width = 0, height = 0;
    std::vector<PixelClass> classes;  // row-major
    PixelClass at(uint32_t x, uint32_t y) const { return classes[size_t{y} * width + x]; }
};
Classification classifyPixels(const scene::Scene& scene, const VisibilityBuffer& visibility);

}  // namespace varc::reference
