// SPDX-License-Identifier: Apache-2.0
// Mesh: procedural sphere, cube and plane with Unity's winding (clockwise front faces in a
// left-handed world: cross(b - a, c - a) points out of the surface).
#include "varc/scene/Mesh.h"

#include <cmath>

#include <glm/gtc/constants.hpp>

namespace varc::scene {
namespace {

constexpr uint32_t kSphereSegments = 48;  // around y
constexpr uint32_t kSphereRings = 24;     // pole to pole

// Tangent handedness w so that cross(n, t) * w points along |bitangent|.
float handedness(const glm::vec3& n, const glm::vec3& t, const glm::vec3& bitangent) {
    return glm::dot(glm::cross(n, t), bitangent) >= 0.0f ? 1.0f : -1.0f;
}

// Rows i = 0..rings from the top pole (theta = 0) down, columns j = 0..segments around y with a
// duplicated seam. u = j/segments, v = 1 - i/rings. Quad (i, j): a = (i, j), b = (i, j+1),
// c = (i+1, j), d = (i+1, j+1). At theta in (0, pi), moving along j is +tangent (d p/d phi) and
// along i is -y-ish, so cross(b - a, c - a) points outwards: triangles (a, b, c) and (b, d, c);
// the one that degenerates at a pole is dropped.
Mesh buildSphere() {
    Mesh m;
    const float pi = glm::pi<float>();
    for (uint32_t i = 0; i <= kSphereRings; ++i) {
        const float theta = pi * static_cast<float>(i) / static_cast<float>(kSphereRings);
        for (uint32_t j = 0; j <= kSphereSegments; ++j) {
            const float phi = 2.0f * pi * static_cast<float>(j) / static_cast<float>(kSphereSegments);
            const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                              std::sin(theta) * std::sin(phi));
            const glm::vec3 unit = glm::normalize(n);
            const glm::vec3 t(-std::sin(phi), 0.0f, std::cos(phi));
            // d p / d v with v = 1 - theta/pi: -d p / d theta.
            const glm::vec3 alongV(-std::cos(theta) * std::cos(phi), std::sin(theta),
                                   -std::cos(theta) * std::sin(phi));
            m.positions.push_back(0.5f * unit);
            m.normals.push_back(unit);
            m.tangents.emplace_back(t, handedness(unit, t, alongV));
            m.uvs.emplace_back(static_cast<float>(j) / static_cast<float>(kSphereSegments),
                               1.0f - static_cast<float>(i) / static_cast<float>(kSphereRings));
        }
    }
    const uint32_t stride = kSphereSegments + 1;
    for (uint32_t i = 0; i < kSphereRings; ++i) {
        for (uint32_t j = 0; j < kSphereSegments; ++j) {
            const uint32_t a = i * stride + j, b = a + 1, c = a + stride, d = c + 1;
            if (i != 0) m.indices.insert(m.indices.end(), {a, b, c});
            if (i != kSphereRings - 1) m.indices.insert(m.indices.end(), {b, d, c});
        }
    }
    m.smoothGroups.assign(m.indices.size() / 3, 0);
    m.boundingRadius = 0.5f;
    return m;
}

// One quad per face: corners 0.5 n ± 0.5 t ± 0.5 b, uv (0,0) at -t-b.
Mesh buildCube() {
    Mesh m;
    struct Face {
        glm::vec3 n, t, b;
    };
    const Face faces[] = {
        {{1, 0, 0}, {0, 0, 1}, {0, 1, 0}},   {{-1, 0, 0}, {0, 0, -1}, {0, 1, 0}},
        {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},   {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}},
        {{0, 0, 1}, {-1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {1, 0, 0}, {0, 1, 0}},
    };
    for (const Face& f : faces) {
        const auto base = static_cast<uint32_t>(m.positions.size());
        for (int k = 0; k < 4; ++k) {
            const float s = (k & 1) ? 1.0f : -1.0f, r = (k & 2) ? 1.0f : -1.0f;
            m.positions.push_back(0.5f * (f.n + s * f.t + r * f.b));
            m.normals.push_back(f.n);
            m.tangents.emplace_back(f.t, handedness(f.n, f.t, f.b));
            m.uvs.emplace_back(0.5f * (s + 1.0f), 0.5f * (r + 1.0f));
        }
        // Corner k: bit 0 = +t, bit 1 = +b. cross(t, b) is +n or -n depending on the face.
        if (glm::dot(glm::cross(f.t, f.b), f.n) > 0.0f) {
            m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base + 1, base + 3, base + 2});
        } else {
            m.indices.insert(m.indices.end(), {base, base + 2, base + 1, base + 1, base + 2, base + 3});
        }
    }
    for (uint32_t face = 0; face < 6; ++face) m.smoothGroups.insert(m.smoothGroups.end(), {face, face});
    m.boundingRadius = std::sqrt(0.75f);
    return m;
}

// 11 x 11 vertices over [-5, 5]² at y = 0, normal +y; u along +x, v along +z. cross(x, z) = -y,
// so quads (a = (i, j), b = (i+1, j), c = (i, j+1), d) use triangles (a, c, b) and (b, c, d).
Mesh buildPlane() {
    Mesh m;
    constexpr uint32_t kQuads = 10;
    for (uint32_t j = 0; j <= kQuads; ++j) {
        for (uint32_t i = 0; i <= kQuads; ++i) {
            const float u = static_cast<float>(i) / kQuads, v = static_cast<float>(j) / kQuads;
            m.positions.emplace_back(10.0f * u - 5.0f, 0.0f, 10.0f * v - 5.0f);
            m.normals.emplace_back(0.0f, 1.0f, 0.0f);
            const glm::vec3 t(1.0f, 0.0f, 0.0f);
            m.tangents.emplace_back(t, handedness(glm::vec3(0, 1, 0), t, glm::vec3(0, 0, 1)));
            m.uvs.emplace_back(u, v);
        }
    }
    for (uint32_t j = 0; j < kQuads; ++j) {
        for (uint32_t i = 0; i < kQuads; ++i) {
            const uint32_t a = j * (kQuads + 1) + i, b = a + 1, c = a + kQuads + 1, d = c + 1;
            m.indices.insert(m.indices.end(), {a, c, b, b, c, d});
        }
    }
    m.smoothGroups.assign(m.indices.size() / 3, 0);
    m.boundingRadius = std::sqrt(50.0f);
    return m;
}

}  // namespace

const Mesh& builtinMesh(MeshKind kind) {
    static const Mesh sphere = buildSphere();
    static const Mesh cube = buildCube();
    static const Mesh plane = buildPlane();
    switch (kind) {
        case MeshKind::Sphere: return sphere;
        case MeshKind::Cube: return cube;
        case MeshKind::Plane: return plane;
    }
    return sphere;
}

}  // namespace varc::scene
