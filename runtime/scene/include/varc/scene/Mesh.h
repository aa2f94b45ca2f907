// SPDX-License-Identifier: Apache-2.0
// Mesh: the procedural built-in meshes (sphere, cube, plane) shared by the GPU renderer and the
// CPU reference.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "varc/scene/Scene.h"

namespace varc::scene {

// Indexed triangle list. Front faces are CLOCKWISE seen from outside in Unity's left-handed world
// (as Unity's own meshes): for a front face (a, b, c), cross(b - a, c - a) points out of the
// surface. The GPU pipeline uses VK_FRONT_FACE_CLOCKWISE with the y-down Vulkan projection of
// SHADER_ABI.md §2. Sphere: radius 0.5 UV sphere (48 x 24 segments) with exact unit normals;
// cube: side 1 with flat per-face normals (24 vertices); plane: 10 x 10 in the xz plane facing +y
// (like Unity's) with 10 x 10 quads. Tangents (xyz, w = ±1 with bitangent = cross(n, t) * w
// pointing along +v) and uv0.
struct Mesh {
    std::vector<glm::vec3> positions, normals;
    std::vector<glm::vec4> tangents;
    std::vector<glm::vec2> uvs;
    std::vector<uint32_t> indices;
    // Per triangle: triangles of different groups meet at a crease (the normal jumps), e.g. the
    // six faces of the cube; the sphere and the plane are one smooth group.
    std::vector<uint32_t> smoothGroups;
    float boundingRadius = 0.0f;  // of a sphere around the object-space origin holding the mesh
};

// The mesh of |kind|, built on first use; thread-safe, never freed.
const Mesh& builtinMesh(MeshKind kind);

}  // namespace varc::scene
