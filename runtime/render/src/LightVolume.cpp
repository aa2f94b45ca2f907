// SPDX-License-Identifier: Apache-2.0
#include "varc/render/LightVolume.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <utility>

namespace varc::render {
namespace {

// Completes a closed convex mesh from its positions and triangles: each triangle wound so that
// cross(b - a, c - a) points away from the vertices' mean (the Mesh.h front-face convention),
// normals pointing away from that mean, dummy tangents and uvs (the light pass reads positions).
scene::Mesh convexMesh(std::vector<glm::vec3> positions, std::vector<uint32_t> indices) {
    glm::vec3 interior(0.0f);
    for (const glm::vec3& p : positions) interior += p;
    interior /= static_cast<float>(positions.size());
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        const glm::vec3& a = positions[indices[t]];
        const glm::vec3 outward =
            glm::cross(positions[indices[t + 1]] - a, positions[indices[t + 2]] - a);
        if (glm::dot(outward, a - interior) < 0.0f) std::swap(indices[t + 1], indices[t + 2]);
    }
    scene::Mesh mesh;
    for (const glm::vec3& p : positions) {
        mesh.normals.push_back(glm::normalize(p - interior));
        mesh.tangents.emplace_back(1.0f, 0.0f, 0.0f, 1.0f);
        mesh.uvs.emplace_back(0.0f);
        mesh.boundingRadius = std::max(mesh.boundingRadius, glm::length(p));
    }
    mesh.positions = std::move(positions);
    mesh.indices = std::move(indices);
    mesh.smoothGroups.assign(mesh.indices.size() / 3, 0);
    return mesh;
}

// Icosahedron subdivided once (42 vertices, 80 faces) on the unit sphere, then pushed out so the
// nearest face plane is at distance 1.
scene::Mesh buildSphereVolume() {
    const float g = (1.0f + std::sqrt(5.0f)) / 2.0f;
    std::vector<glm::vec3> positions = {{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0},
                                        {0, -1, g}, {0, 1, g}, {0, -1, -g}, {0, 1, -g},
                                        {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    for (glm::vec3& p : positions) p = glm::normalize(p);
    const std::vector<uint32_t> icosahedron = {
        0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
        4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
        6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
    auto midpoint = [&](uint32_t a, uint32_t b) {
        auto key = std::minmax(a, b);
        auto [it, inserted] = midpoints.emplace(key, static_cast<uint32_t>(positions.size()));
        if (inserted) positions.push_back(glm::normalize(positions[a] + positions[b]));
        return it->second;
    };
    std::vector<uint32_t> indices;
    for (size_t t = 0; t < icosahedron.size(); t += 3) {
        const uint32_t a = icosahedron[t], b = icosahedron[t + 1], c = icosahedron[t + 2];
        const uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
        indices.insert(indices.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    scene::Mesh mesh = convexMesh(std::move(positions), std::move(indices));
    float nearestPlane = 1.0f;
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
        const glm::vec3& a = mesh.positions[mesh.indices[t]];
        const glm::vec3 n = glm::normalize(glm::cross(mesh.positions[mesh.indices[t + 1]] - a,
                                                      mesh.positions[mesh.indices[t + 2]] - a));
        nearestPlane = std::min(nearestPlane, glm::dot(n, a));
    }
    // A hair beyond 1 so float rounding of the scaled vertices never cuts into the ball.
    const float scale = 1.001f / nearestPlane;
    for (glm::vec3& p : mesh.positions) p *= scale;
    mesh.boundingRadius *= scale;
    return mesh;
}

scene::Mesh buildPyramidVolume() {
    return convexMesh({{0, 0, 0}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}},
                      {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 1, 1, 3, 2, 1, 4, 3});
}

// Largest signed distance of |point| to the face planes of |mesh| placed by |toWorld|: <= 0
// inside the (convex) volume, and a lower bound of the distance to it outside.
float signedDistanceToVolume(const scene::Mesh& mesh, const glm::mat4& toWorld,
                             const glm::vec3& point) {
    float distance = -INFINITY;
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const glm::vec3 a(toWorld * glm::vec4(mesh.positions[mesh.indices[t]], 1.0f));
        const glm::vec3 b(toWorld * glm::vec4(mesh.positions[mesh.indices[t + 1]], 1.0f));
        const glm::vec3 c(toWorld * glm::vec4(mesh.positions[mesh.indices[t + 2]], 1.0f));
        const glm::vec3 n = glm::normalize(glm::cross(b - a, c - a));
        distance = std::max(distance, glm::dot(n, point - a));
    }
    return distance;
}

// The farthest any point of the near-plane rectangle is from the camera position.
float nearPlaneCornerDistance(const scene::Camera& camera) {
    const float tanY = std::tan(glm::radians(camera.fovY) * 0.5f);
    const float aspect = static_cast<float>(camera.width) / static_cast<float>(camera.height);
    return camera.nearPlane * std::sqrt(1.0f + tanY * tanY * (1.0f + aspect * aspect));
}

bool reachesPastFarPlane(const scene::Mesh& mesh, const glm::mat4& toWorld,
                         const scene::Camera& camera, const scene::CameraMatrices& matrices) {
    const glm::mat4 toCamera = matrices.worldToCamera * toWorld;
    return std::any_of(mesh.positions.begin(), mesh.positions.end(), [&](const glm::vec3& p) {
        return (toCamera * glm::vec4(p, 1.0f)).z >= camera.farPlane;
    });
}

}  // namespace

const scene::Mesh& unitSphereVolume() {
    static const scene::Mesh mesh = buildSphereVolume();
    return mesh;
}

const scene::Mesh& unitPyramidVolume() {
    static const scene::Mesh mesh = buildPyramidVolume();
    return mesh;
}

LightVolume chooseLightVolume(const scene::Light& light, const scene::Camera& camera,
                              const scene::CameraMatrices& matrices) {
    LightVolume volume;
    if (light.type == scene::LightType::Directional) return volume;
    if (light.type == scene::LightType::Point) {
        volume.mesh = &unitSphereVolume();
        volume.objectToWorld = glm::scale(light.transform.rigidToWorld(), glm::vec3(light.range));
    } else {
        const float halfWidth = light.range * std::tan(glm::radians(light.spotAngle) * 0.5f);
        volume.mesh = &unitPyramidVolume();
        volume.objectToWorld = glm::scale(light.transform.rigidToWorld(),
                                          glm::vec3(halfWidth, halfWidth, light.range));
    }
    // 1 % and a micrometre of slack for the rounding of the distances themselves.
    const float margin = nearPlaneCornerDistance(camera) * 1.01f + 1e-6f;
    if (signedDistanceToVolume(*volume.mesh, volume.objectToWorld, camera.position) >= margin) {
        volume.draw = LightVolumeDraw::FrontFaces;
    } else if (reachesPastFarPlane(*volume.mesh, volume.objectToWorld, camera, matrices)) {
        volume = LightVolume{};
    } else {
        volume.draw = LightVolumeDraw::BackFaces;
    }
    return volume;
}

}  // namespace varc::render
