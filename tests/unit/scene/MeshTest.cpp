// SPDX-License-Identifier: Apache-2.0
// builtinMesh: sizes, unit normals, and Unity's winding (clockwise seen from outside).
#include <gtest/gtest.h>

#include "varc/scene/CameraMatrices.h"
#include "varc/scene/Mesh.h"

namespace varc::scene {
namespace {

glm::vec3 faceCross(const Mesh& m, size_t t) {
    const glm::vec3 a = m.positions[m.indices[3 * t]], b = m.positions[m.indices[3 * t + 1]],
                    c = m.positions[m.indices[3 * t + 2]];
    return glm::cross(b - a, c - a);
}

glm::vec3 centroid(const Mesh& m, size_t t) {
    return (m.positions[m.indices[3 * t]] + m.positions[m.indices[3 * t + 1]] +
            m.positions[m.indices[3 * t + 2]]) / 3.0f;
}

// In a left-handed world a triangle is clockwise seen from the side cross(b - a, c - a) points
// to (Unity's quad: (-.5,-.5,0), (.5,.5,0), (.5,-.5,0) faces -z and cross = (0,0,-1)).
TEST(Mesh, EverySphereTriangleIsClockwiseFromOutside) {
    const Mesh& m = builtinMesh(MeshKind::Sphere);
    ASSERT_EQ(m.indices.size() % 3, 0u);
    for (size_t t = 0; t < m.indices.size() / 3; ++t) {
        EXPECT_GT(glm::dot(faceCross(m, t), centroid(m, t)), 0.0f) << "triangle " << t;
    }
    // 48 x 24 quads minus one triangle per quad in the two pole rings.
    EXPECT_EQ(m.indices.size() / 3, 48u * 24u * 2u - 2u * 48u);
}

TEST(Mesh, CubeAndPlaneTrianglesFaceTheirNormals) {
    for (MeshKind kind : {MeshKind::Cube, MeshKind::Plane}) {
        const Mesh& m = builtinMesh(kind);
        for (size_t t = 0; t < m.indices.size() / 3; ++t) {
            const glm::vec3 n = m.normals[m.indices[3 * t]];
            EXPECT_GT(glm::dot(faceCross(m, t), n), 0.0f) << toString(kind) << " triangle " << t;
        }
    }
    EXPECT_EQ(builtinMesh(MeshKind::Cube).positions.size(), 24u);
    EXPECT_EQ(builtinMesh(MeshKind::Cube).indices.size(), 36u);
    EXPECT_EQ(builtinMesh(MeshKind::Plane).positions.size(), 121u);
    EXPECT_EQ(builtinMesh(MeshKind::Plane).indices.size(), 600u);
    EXPECT_EQ(builtinMesh(MeshKind::Plane).normals[0], glm::vec3(0, 1, 0));
}

TEST(Mesh, SphereHasRadiusHalfAndExactNormals) {
    const Mesh& m = builtinMesh(MeshKind::Sphere);
    for (size_t i = 0; i < m.positions.size(); ++i) {
        EXPECT_NEAR(glm::length(m.positions[i]), 0.5f, 1e-6f);
        EXPECT_NEAR(glm::length(m.normals[i]), 1.0f, 1e-6f);
        EXPECT_NEAR(glm::distance(m.normals[i], m.positions[i] * 2.0f), 0.0f, 1e-6f);
        EXPECT_NEAR(glm::dot(glm::vec3(m.tangents[i]), m.normals[i]), 0.0f, 1e-5f);
        EXPECT_EQ(std::abs(m.tangents[i].w), 1.0f);
    }
}

// Seen through the Vulkan projection (y down), front faces are clockwise in framebuffer space:
// Vulkan's area a = -1/2 Σ (x_i y_{i+1} - x_{i+1} y_i) is negative (VK_FRONT_FACE_CLOCKWISE).
TEST(Mesh, CameraFacingTrianglesAreClockwiseInFramebuffer) {
    Camera c;
    const CameraMatrices cm = cameraMatrices(c);
    const Mesh& m = builtinMesh(MeshKind::Sphere);
    int facing = 0;
    for (size_t t = 0; t < m.indices.size() / 3; ++t) {
        const glm::vec3 n = glm::normalize(faceCross(m, t));
        const bool towardsCamera = glm::dot(n, c.position - centroid(m, t)) > 1e-3f;
        float sum = 0.0f;
        glm::vec2 fb[3];
        for (int k = 0; k < 3; ++k) {
            const glm::vec4 clip = cm.viewProjection * glm::vec4(m.positions[m.indices[3 * t + k]], 1);
            fb[k] = (glm::vec2(clip) / clip.w + 1.0f) * 128.0f;
        }
        for (int k = 0; k < 3; ++k) sum += fb[k].x * fb[(k + 1) % 3].y - fb[(k + 1) % 3].x * fb[k].y;
        const float vulkanArea = -0.5f * sum;
        if (towardsCamera) {
            ++facing;
            EXPECT_LT(vulkanArea, 0.0f) << "triangle " << t;
        }
    }
    EXPECT_GT(facing, 400);
}

}  // namespace
}  // namespace varc::scene
