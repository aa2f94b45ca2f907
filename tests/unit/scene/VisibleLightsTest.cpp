// SPDX-License-Identifier: Apache-2.0
// selectVisibleLights and objectLightList: the single-pass light rules (docs/LIGHTING.md §9.3).
#include <gtest/gtest.h>

#include "varc/scene/VisibleLights.h"

namespace varc::scene {
namespace {

Light point(glm::vec3 position, float range, float intensity = 1.0f) {
    Light l;
    l.type = LightType::Point;
    l.transform.position = position;
    l.range = range;
    l.intensity = intensity;
    return l;
}

Light directional(float intensity) {
    Light l;
    l.type = LightType::Directional;
    l.intensity = intensity;
    return l;
}

// Camera at z = -5 looking at the origin (the default Camera); one unit sphere at the origin.
Scene sceneWith(std::vector<Light> lights) {
    Scene s;
    s.camera.path = RenderPath::SinglePass;
    s.objects.push_back(Object{});
    s.lights = std::move(lights);
    return s;
}

TEST(VisibleLights, LightsOutsideTheFrustumAreNotVisible) {
    // Behind the camera, 7 m from the near plane with range 2: cannot touch the frustum.
    // Far to the side (60 m at x): outside the left/right planes. Directional: always visible.
    Scene s = sceneWith({point({0, 0, -12}, 2.0f), point({60, 0, 0}, 3.0f), directional(1.0f), point({0, 0, 1}, 3.0f)});
    const VisibleLightSet visible = selectVisibleLights(s);
    EXPECT_EQ(visible.slots, (std::vector<int>{2, 3}));
    EXPECT_TRUE(visible.dropped.empty());
}

TEST(VisibleLights, ALightWhoseRangeReachesIntoTheFrustumIsVisible) {
    // Behind the camera (z = -8, camera at -5, near 0.1) but with range 4 it reaches z = -4.
    Scene s = sceneWith({point({0, 0, -8}, 4.0f)});
    EXPECT_EQ(selectVisibleLights(s).slots, std::vector<int>{0});
}

TEST(VisibleLights, OrderedByImportanceThenBrightnessAtTheCamera) {
    Light important = point({0, 0, 3}, 5.0f, 0.1f);
    important.renderMode = LightRenderMode::Important;
    Light notImportant = directional(10.0f);
    notImportant.renderMode = LightRenderMode::NotImportant;
    Scene s = sceneWith({point({0, 0, 3}, 5.0f, 1.0f), notImportant, point({0, 0, -3}, 5.0f, 1.0f), important});
    // Important first; then the Auto point lights, the one nearer the camera (z = -3) brighter;
    // NotImportant last whatever its intensity.
    EXPECT_EQ(selectVisibleLights(s).slots, (std::vector<int>{3, 2, 0, 1}));
}

TEST(VisibleLights, BeyondSixteenLightsTheLeastImportantAreDropped) {
    std::vector<Light> lights;
    for (int i = 0; i < 20; ++i) lights.push_back(point({0, 0, 0}, 5.0f, 1.0f + static_cast<float>(i)));
    const VisibleLightSet visible = selectVisibleLights(sceneWith(lights));
    ASSERT_EQ(visible.slots.size(), 16u);
    EXPECT_EQ(visible.slots.front(), 19);  // brightest
    EXPECT_EQ(visible.slots.back(), 4);
    EXPECT_EQ(visible.dropped, (std::vector<int>{3, 2, 1, 0}));
}

TEST(VisibleLights, ObjectListHoldsOnlySlotsThatReachTheObjectBrightestFirst) {
    // Slot order (brightness at the camera, 5 m before the origin): light 2 (3 m away), light 1
    // (9 m, but intensity 5), light 0 (6.5 m).
    Scene s = sceneWith({point({0, 0, 1.5f}, 2.0f, 1.0f), point({0, 0, 4.0f}, 2.0f, 5.0f),
                         point({0, 0, -2.0f}, 3.0f, 0.5f)});
    const VisibleLightSet visible = selectVisibleLights(s);
    ASSERT_EQ(visible.slots, (std::vector<int>{2, 1, 0}));
    const ObjectLightList list = objectLightList(s, visible, s.objects[0]);
    // Light 1 is 4 m away with range 2: 4 >= 2 + 0.5, out of reach. At the sphere's centre light 0
    // (slot 2; 1.5 m, range 2) is brighter than light 2 (slot 0; 2 m, range 3, intensity 0.5).
    EXPECT_EQ(list.count, 2);
    EXPECT_EQ(list.slots, (std::vector<int>{2, 0}));
}

TEST(VisibleLights, ObjectListKeepsTheCountButAtMostEightSlots) {
    std::vector<Light> lights;
    for (int i = 0; i < 12; ++i) lights.push_back(directional(1.0f + static_cast<float>(i)));
    Scene s = sceneWith(lights);
    const ObjectLightList list = objectLightList(s, selectVisibleLights(s), s.objects[0]);
    EXPECT_EQ(list.count, 12);
    EXPECT_EQ(list.slots, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));
}

TEST(VisibleLights, NoLightsGiveAnEmptyList) {
    Scene s = sceneWith({});
    const VisibleLightSet visible = selectVisibleLights(s);
    EXPECT_TRUE(visible.slots.empty());
    const ObjectLightList list = objectLightList(s, visible, s.objects[0]);
    EXPECT_EQ(list.count, 0);
    EXPECT_TRUE(list.slots.empty());
}

}  // namespace
}  // namespace varc::scene
