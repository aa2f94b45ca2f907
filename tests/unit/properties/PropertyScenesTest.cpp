// SPDX-License-Identifier: Apache-2.0
// PropertyScenes: the out-of-range lights reach object bounds but no surface, the key lights
// reach every object, and similar() moves everything consistently.
#include <gtest/gtest.h>

#include "varc/properties/PropertyScenes.h"
#include "varc/scene/ForwardLights.h"
#include "varc/scene/LightImportance.h"

namespace varc::properties {
namespace {

// The distance from |p| to the nearest surface point of the generated scene's |object| (the
// cube rotated about y only, so its top face stays at y = 0.5; the plane is y = -0.5).
float surfaceDistance(const scene::Object& object, glm::vec3 p) {
    glm::vec3 local = p - object.transform.position;
    switch (object.mesh) {
        case scene::MeshKind::Sphere:
            return glm::length(local) - 0.5f;
        case scene::MeshKind::Cube: {
            glm::vec3 unrotated = glm::transpose(object.transform.rotation()) * local;
            glm::vec3 outside = glm::max(glm::abs(unrotated) - glm::vec3(0.5f), glm::vec3(0.0f));
            return glm::length(outside);
        }
        case scene::MeshKind::Plane: {
            float half = 5.0f * object.transform.scale.x;
            glm::vec2 outside = glm::max(glm::abs(glm::vec2(local.x, local.z)) - half, 0.0f);
            return glm::length(glm::vec3(outside.x, local.y, outside.y));
        }
    }
    return 0;
}

TEST(PropertyScenesTest, OutOfRangeLightsReachBoundsButNoSurface) {
    scene::Scene scene = emptyScene("s", true, 64);
    for (const scene::Light& light : {outOfRangePoint(), outOfRangeSpot()}) {
        int reached = 0;
        for (const scene::Object& object : scene.objects) {
            if (scene::lightReaches(light, scene::worldBounds(object))) ++reached;
            EXPECT_GT(surfaceDistance(object, light.transform.position), light.range)
                << scene::toString(object.mesh);
        }
        EXPECT_EQ(reached, 2) << "the cube and the plane draw the light";
    }
}

TEST(PropertyScenesTest, KeyLightsReachEveryObject) {
    scene::Scene scene = emptyScene("s", true, 64);
    for (const scene::Light& light : {keyPoint(), keySpot()}) {
        for (const scene::Object& object : scene.objects)
            EXPECT_TRUE(scene::lightReaches(light, scene::worldBounds(object)));
    }
}

TEST(PropertyScenesTest, SimilarMovesAndScalesEverything) {
    scene::Scene scene = withLights(emptyScene("s", true, 64), {keyPoint(), keyDirectional()});
    scene::Scene moved = similar(scene, 2.0f, {1.0f, 2.0f, 3.0f});
    EXPECT_EQ(moved.camera.position, 2.0f * scene.camera.position + glm::vec3(1, 2, 3));
    EXPECT_EQ(moved.camera.target, 2.0f * scene.camera.target + glm::vec3(1, 2, 3));
    EXPECT_FLOAT_EQ(moved.camera.nearPlane, 2.0f * scene.camera.nearPlane);
    EXPECT_EQ(moved.objects[2].transform.scale, 2.0f * scene.objects[2].transform.scale);
    EXPECT_EQ(moved.objects[1].transform.rotationDegrees,
              scene.objects[1].transform.rotationDegrees);
    EXPECT_FLOAT_EQ(moved.lights[0].range, 2.0f * scene.lights[0].range);
    EXPECT_EQ(moved.lights[0].transform.position,
              2.0f * scene.lights[0].transform.position + glm::vec3(1, 2, 3));
    EXPECT_EQ(moved.lights[1].transform.rotationDegrees, scene.lights[1].transform.rotationDegrees);
}

TEST(PropertyScenesTest, TurnedTurnsPositionsAndDirectionsAlike) {
    scene::Scene scene = withLights(emptyScene("s", true, 64), {keyPoint(), keyDirectional()});
    scene::Scene turnedScene = turned(scene, 90.0f);
    // Ry(90) maps +z to +x and +x to -z.
    glm::vec3 camera = turnedScene.camera.position, expected = scene.camera.position;
    EXPECT_NEAR(camera.x, expected.z, 1e-5f);
    EXPECT_NEAR(camera.z, -expected.x, 1e-5f);
    EXPECT_NEAR(camera.y, expected.y, 1e-5f);
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        glm::vec3 forward = turnedScene.lights[i].forward(), original = scene.lights[i].forward();
        EXPECT_NEAR(forward.x, original.z, 1e-5f);
        EXPECT_NEAR(forward.z, -original.x, 1e-5f);
    }
    // The object's local axes turn with it: its local +x is turned like a position.
    glm::mat3 before = scene.objects[1].transform.rotation();
    glm::mat3 after = turnedScene.objects[1].transform.rotation();
    EXPECT_NEAR(after[0].x, before[0].z, 1e-5f);
    EXPECT_NEAR(after[0].z, -before[0].x, 1e-5f);
}

TEST(PropertyScenesTest, ObjectsTurnedAboutTheLightAxisSeenFromAbove) {
    scene::Scene scene = fromAbove(withLights(
        emptyScene("s", true, 64), {overheadDirectional(), onLightAxis(keyPoint(), 1.6f)}));
    EXPECT_EQ(scene.camera.position, glm::vec3(0.0f, 6.5f, 0.0f));
    EXPECT_EQ(scene.camera.target, glm::vec3(0.0f));
    glm::vec3 down = scene.lights[0].forward();
    EXPECT_NEAR(down.x, 0.0f, 1e-6f);
    EXPECT_NEAR(down.y, -1.0f, 1e-6f);
    EXPECT_NEAR(down.z, 0.0f, 1e-6f);
    EXPECT_EQ(scene.lights[1].transform.position, glm::vec3(0.0f, 1.6f, 0.0f));
    scene::Scene turnedScene = objectsTurned(scene, 90.0f);
    // The camera and the lights stay; the objects turn as turned() turns them.
    EXPECT_EQ(turnedScene.camera.position, scene.camera.position);
    EXPECT_EQ(turnedScene.lights[0].transform.rotationDegrees,
              scene.lights[0].transform.rotationDegrees);
    EXPECT_EQ(turnedScene.lights[1].transform.position, scene.lights[1].transform.position);
    scene::Scene both = turned(scene, 90.0f);
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        EXPECT_EQ(turnedScene.objects[i].transform.position, both.objects[i].transform.position);
        EXPECT_EQ(turnedScene.objects[i].transform.rotationDegrees,
                  both.objects[i].transform.rotationDegrees);
    }
    EXPECT_NEAR(turnedScene.objects[0].transform.position.z, 1.2f, 1e-5f);  // sphere: -x -> +z
}

TEST(PropertyScenesTest, EveryObjectUsesTheShaderWithItsDefaults) {
    scene::Scene scene = emptyScene("varc/Forward", false, 48);
    ASSERT_EQ(scene.objects.size(), 3u);
    for (const scene::Object& object : scene.objects) {
        EXPECT_EQ(object.material.shader, "varc/Forward");
        EXPECT_TRUE(object.material.properties.empty());
    }
    EXPECT_EQ(scene.camera.width, 48u);
    EXPECT_FALSE(scene.camera.hdr);
    EXPECT_TRUE(scene.lights.empty());
}

}  // namespace
}  // namespace varc::properties
