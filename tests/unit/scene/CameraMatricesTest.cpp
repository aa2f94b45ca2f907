// SPDX-License-Identifier: Apache-2.0
// cameraMatrices: look-at frame in Unity's conventions, Vulkan projection (y down, depth 0..1).
#include <cmath>

#include <gtest/gtest.h>

#include "varc/scene/CameraMatrices.h"

namespace varc::scene {
namespace {

// Framebuffer position (pixels, y down) and depth of world point |p|.
glm::vec3 toFramebuffer(const CameraMatrices& m, const Camera& c, const glm::vec3& p) {
    const glm::vec4 clip = m.viewProjection * glm::vec4(p, 1.0f);
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    return {(ndc.x + 1.0f) * 0.5f * static_cast<float>(c.width),
            (ndc.y + 1.0f) * 0.5f * static_cast<float>(c.height), ndc.z};
}

TEST(CameraMatrices, PointsLandAtExpectedPixels) {
    Camera c;  // at (0,0,-5) looking at the origin, 60° vertical, 256 x 256
    const CameraMatrices m = cameraMatrices(c);
    const glm::vec3 centre = toFramebuffer(m, c, {0, 0, 0});
    EXPECT_NEAR(centre.x, 128.0f, 1e-3f);
    EXPECT_NEAR(centre.y, 128.0f, 1e-3f);
    // 1 m right at 5 m: ndc x = 1 / (5 tan 30°) = 0.34641; pixel (1.34641 / 2) * 256.
    const float k = 1.0f / (5.0f * std::tan(glm::radians(30.0f)));
    const glm::vec3 right = toFramebuffer(m, c, {1, 0, 0});
    EXPECT_NEAR(right.x, (1.0f + k) * 128.0f, 1e-3f);
    EXPECT_NEAR(right.y, 128.0f, 1e-3f);
    // World up is towards row 0.
    const glm::vec3 up = toFramebuffer(m, c, {0, 1, 0});
    EXPECT_NEAR(up.y, (1.0f - k) * 128.0f, 1e-3f);
}

TEST(CameraMatrices, AspectScalesX) {
    Camera c;
    c.width = 512;
    c.height = 256;
    const CameraMatrices m = cameraMatrices(c);
    const float k = 1.0f / (5.0f * std::tan(glm::radians(30.0f)) * 2.0f);
    EXPECT_NEAR(toFramebuffer(m, c, {1, 0, 0}).x, (1.0f + k) * 256.0f, 1e-3f);
}

TEST(CameraMatrices, DepthIsZeroAtNearAndOneAtFar) {
    Camera c;
    c.nearPlane = 0.5f;
    c.farPlane = 20.0f;
    const CameraMatrices m = cameraMatrices(c);
    EXPECT_NEAR(toFramebuffer(m, c, {0, 0, -4.5f}).z, 0.0f, 1e-6f);
    EXPECT_NEAR(toFramebuffer(m, c, {0, 0, 15.0f}).z, 1.0f, 1e-5f);
    const float mid = toFramebuffer(m, c, {0, 0, 0}).z;
    EXPECT_GT(mid, 0.0f);
    EXPECT_LT(mid, 1.0f);
    // GL projection of the near plane point is z = -w.
    const glm::vec4 gl = m.glProjection * m.view * glm::vec4(0, 0, -4.5f, 1);
    EXPECT_NEAR(gl.z / gl.w, -1.0f, 1e-5f);
    EXPECT_NEAR(gl.y, 0.0f, 1e-6f);
}

TEST(CameraMatrices, ViewLooksDownNegativeZ) {
    Camera c;
    const CameraMatrices m = cameraMatrices(c);
    const glm::vec4 v = m.view * glm::vec4(0, 0, 0, 1);
    EXPECT_NEAR(v.z, -5.0f, 1e-5f);
    const glm::vec4 local = m.worldToCamera * glm::vec4(0, 0, 0, 1);
    EXPECT_NEAR(local.z, 5.0f, 1e-5f);
}

// A camera looking along +x has the frame of a Unity transform rotated by (0, 90, 0).
TEST(CameraMatrices, FrameMatchesUnityRotation) {
    Camera c;
    c.position = {1, 2, 3};
    c.target = {5, 2, 3};
    Transform t;
    t.position = c.position;
    t.rotationDegrees = {0, 90, 0};
    const glm::mat4 expected = t.rigidToWorld();
    const glm::mat4 actual = cameraMatrices(c).cameraToWorld;
    for (int col = 0; col < 4; ++col) {
        for (int row = 0; row < 4; ++row) EXPECT_NEAR(actual[col][row], expected[col][row], 1e-5f);
    }
}

TEST(CameraMatrices, LookingStraightDownStaysFinite) {
    Camera c;
    c.position = {0, 10, 0};
    c.target = {0, 0, 0};
    const CameraMatrices m = cameraMatrices(c);
    const glm::vec3 p = toFramebuffer(m, c, {0, 0, 0});
    EXPECT_NEAR(p.x, 128.0f, 1e-3f);
    EXPECT_NEAR(p.y, 128.0f, 1e-3f);
    // World up (0,0,1) is the camera's up: +z lands above the centre.
    EXPECT_LT(toFramebuffer(m, c, {0, 0, 1}).y, 128.0f);
}

}  // namespace
}  // namespace varc::scene
