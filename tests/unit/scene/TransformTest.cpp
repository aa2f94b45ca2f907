// SPDX-License-Identifier: Apache-2.0
// Transform and Light::forward: Unity's Euler order (z, then x, then y) and T * R * S.
#include <gtest/gtest.h>

#include "varc/scene/Scene.h"

namespace varc::scene {
namespace {

void expectNear(const glm::vec3& a, const glm::vec3& b) {
    EXPECT_NEAR(a.x, b.x, 1e-5f);
    EXPECT_NEAR(a.y, b.y, 1e-5f);
    EXPECT_NEAR(a.z, b.z, 1e-5f);
}

glm::vec3 rotate(const glm::vec3& degrees, const glm::vec3& v) {
    Transform t;
    t.rotationDegrees = degrees;
    return t.rotation() * v;
}

// Unity: Quaternion.Euler(90,0,0) * forward = down; Euler(0,90,0) * forward = right;
// Euler(0,0,90) * right = up.
TEST(Transform, SingleAxisRotationsMatchUnity) {
    expectNear(rotate({90, 0, 0}, {0, 0, 1}), {0, -1, 0});
    expectNear(rotate({0, 90, 0}, {0, 0, 1}), {1, 0, 0});
    expectNear(rotate({0, 0, 90}, {1, 0, 0}), {0, 1, 0});
}

// Euler (90, 0, 90) applies z first: right -> up (Rz) -> forward (Rx). x first would give up.
TEST(Transform, EulerOrderIsZThenXThenY) {
    expectNear(rotate({90, 0, 90}, {1, 0, 0}), {0, 0, 1});
    // (90, 90, 0): right stays right under Rx, then Ry(90) maps +x to -z.
    expectNear(rotate({90, 90, 0}, {1, 0, 0}), {0, 0, -1});
    expectNear(rotate({90, 90, 0}, {0, 0, 1}), {0, -1, 0});
}

TEST(Transform, LocalToWorldIsTranslateRotateScale) {
    Transform t;
    t.position = {0, 0, 5};
    t.rotationDegrees = {0, 90, 0};
    t.scale = {2, 1, 1};
    // (1,0,0) -> scale (2,0,0) -> Ry(90) (0,0,-2) -> translate (0,0,3).
    expectNear(glm::vec3(t.localToWorld() * glm::vec4(1, 0, 0, 1)), {0, 0, 3});
    expectNear(glm::vec3(t.rigidToWorld() * glm::vec4(1, 0, 0, 1)), {0, 0, 4});
}

TEST(Transform, LightForwardIsLocalZ) {
    Light light;
    light.transform.rotationDegrees = {90, 0, 0};
    expectNear(light.forward(), {0, -1, 0});
    light.transform.rotationDegrees = {0, 180, 0};
    expectNear(light.forward(), {0, 0, -1});
}

}  // namespace
}  // namespace varc::scene
