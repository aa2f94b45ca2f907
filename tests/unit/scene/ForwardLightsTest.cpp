// SPDX-License-Identifier: Apache-2.0
// assignForwardLights (docs/LIGHTING.md §9) and the SH coefficients and packing (§5).
#include <gtest/gtest.h>

#include "varc/scene/ForwardLights.h"

namespace varc::scene {
namespace {

Light directional(float intensity, std::string cookie = "none") {
    Light l;
    l.type = LightType::Directional;
    l.intensity = intensity;
    l.cookie = std::move(cookie);
    return l;
}

Light point(glm::vec3 position, float range, float intensity = 1.0f) {
    Light l;
    l.type = LightType::Point;
    l.transform.position = position;
    l.range = range;
    l.intensity = intensity;
    return l;
}

Scene sceneWith(std::vector<Light> lights, int pixelLightCount = 4) {
    Scene s;
    s.objects.push_back(Object{});  // unit sphere (radius 0.5) at the origin
    s.lights = std::move(lights);
    s.pixelLightCount = pixelLightCount;
    return s;
}

TEST(ForwardLights, PointLightOutOfRangeIsIgnored) {
    // 3 m away with range 2: 3 >= 2 + 0.5, so it cannot reach the sphere.
    Scene s = sceneWith({point({3, 0, 0}, 2.0f), point({2.4f, 0, 0}, 2.0f)});
    const ForwardLightAssignment a = assignForwardLights(s, s.objects[0]);
    EXPECT_EQ(a.addLights, std::vector<int>{1});
    EXPECT_TRUE(a.vertexLights.empty());
    EXPECT_TRUE(a.shLights.empty());
}

TEST(ForwardLights, BrightestDirectionalIsMain) {
    Scene s = sceneWith({directional(0.5f), directional(2.0f), directional(1.0f)});
    const ForwardLightAssignment a = assignForwardLights(s, s.objects[0]);
    EXPECT_EQ(a.mainDirectional, 1);
    // The other two are Auto pixel lights within the budget of 4, brightest first.
    EXPECT_EQ(a.addLights, (std::vector<int>{2, 0}));
}

TEST(ForwardLights, DirectionalWithCookieGoesToAddPasses) {
    Scene s = sceneWith({directional(2.0f, "default"), directional(1.0f)}, 0);
    const ForwardLightAssignment a = assignForwardLights(s, s.objects[0]);
    EXPECT_EQ(a.mainDirectional, -1);
    // Always a pixel light, even with pixel_light_count 0; the other directional light falls to SH.
    EXPECT_EQ(a.addLights, std::vector<int>{0});
    EXPECT_EQ(a.shLights, std::vector<int>{1});
}

TEST(ForwardLights, PixelLightCountZeroMakesPointLightsVertexLights) {
    Scene s = sceneWith({directional(1.0f), point({1, 0, 0}, 5.0f)}, 0);
    const ForwardLightAssignment a = assignForwardLights(s, s.objects[0]);
    EXPECT_EQ(a.mainDirectional, 0);
    EXPECT_TRUE(a.addLights.empty());
    EXPECT_EQ(a.vertexLights, std::vector<int>{1});
}

TEST(ForwardLights, MainLightCountsTowardsPixelLightCount) {
    Scene s = sceneWith({directional(1.0f), point({1, 0, 0}, 5.0f, 2.0f), point({-1, 0, 0}, 5.0f, 1.0f)}, 2);
    const ForwardLightAssignment a = assignForwardLights(s, s.objects[0]);
    EXPECT_EQ(a.mainDirectional, 0);
    EXPECT_EQ(a.addLights, std::vector<int>{1});     // the brighter point light
    EXPECT_EQ(a.vertexLights, std::vector<int>{2});
}

TEST(ForwardLights, MoreThanFourPointLightsSpillIntoSH) {
    std::vector<Light> lights;
    for (int i = 0; i < 6; ++i) lights.push_back(point({1, 0, 0}, 5.0f, 1.0f + static_cast<float>(i)));
    Scene s = sceneWith(lights, 0);
    const ForwardLightAssignment a = assignForwardLights(s, s.objects[0]);
    EXPECT_EQ(a.vertexLights, (std::vector<int>{5, 4, 3, 2}));  // brightest first
    EXPECT_EQ(a.shLights, (std::vector<int>{1, 0}));
}

TEST(ForwardLights, ImportantBeatsBudgetAndNotImportantNeverPixel) {
    std::vector<Light> lights = {point({1, 0, 0}, 5.0f, 1.0f), point({1, 0, 0}, 5.0f, 5.0f),
                                 point({1, 0, 0}, 5.0f, 9.0f)};
    lights[0].renderMode = LightRenderMode::Important;
    lights[2].renderMode = LightRenderMode::NotImportant;
    Scene s = sceneWith(lights, 1);
    const ForwardLightAssignment a = assignForwardLights(s, s.objects[0]);
    // Important first (uses the one slot), the Auto light no longer fits, NotImportant never.
    EXPECT_EQ(a.addLights, std::vector<int>{0});
    EXPECT_EQ(a.vertexLights, (std::vector<int>{1, 2}));
}

TEST(ForwardLights, SpotLightsAreNeverVertexLights) {
    Light spot = point({1, 0, 0}, 5.0f);
    spot.type = LightType::Spot;
    Scene s = sceneWith({spot}, 0);
    const ForwardLightAssignment a = assignForwardLights(s, s.objects[0]);
    EXPECT_TRUE(a.vertexLights.empty());
    EXPECT_EQ(a.shLights, std::vector<int>{0});
}

TEST(ForwardLights, BrightnessUsesDistanceAttenuation) {
    // Same intensity: the nearer light is brighter; 1/(1 + 25 d²/r²) at d = 1, r = 5 is 0.5.
    const Light l = point({1, 0, 0}, 5.0f);
    EXPECT_NEAR(lightBrightnessAt(l, glm::vec3(0.0f)), 0.5f, 1e-6f);
    Scene s = sceneWith({point({2, 0, 0}, 5.0f), point({1, 0, 0}, 5.0f)}, 1);
    EXPECT_EQ(assignForwardLights(s, s.objects[0]).addLights, std::vector<int>{1});
}

TEST(ForwardLights, FlatAmbientPacking) {
    Scene s = sceneWith({});
    s.ambient = {0.1f, 0.2f, 0.3f};
    const auto sh = packedSH(s, s.objects[0], {});
    EXPECT_EQ(sh[0], glm::vec4(0, 0, 0, 0.1f));
    EXPECT_EQ(sh[1], glm::vec4(0, 0, 0, 0.2f));
    EXPECT_EQ(sh[2], glm::vec4(0, 0, 0, 0.3f));
    for (int i = 3; i < 6; ++i) EXPECT_EQ(sh[i], glm::vec4(0.0f));
    EXPECT_EQ(sh[6], glm::vec4(0, 0, 0, 1));
    const glm::vec3 e = shadeSH9(sh, glm::normalize(glm::vec3(0.3f, -0.5f, 0.8f)));
    EXPECT_NEAR(e.x, 0.1f, 1e-6f);
    EXPECT_NEAR(e.z, 0.3f, 1e-6f);
}

// Order-2 SH of the clamped cosine: 1/4 + 1/2 cos + 5/16 (3cos² - 1)/2·2 → 1.0625 towards the
// light, 0.0625 away from it, 0.25 - 5/32 = 0.09375 at 90°; for any light direction.
TEST(ForwardLights, DirectionalLightInSH) {
    Light l = directional(2.0f);
    l.transform.rotationDegrees = {30, 60, 0};
    Scene s = sceneWith({l});
    const auto sh = packedSH(s, s.objects[0], {0});
    const glm::vec3 toLight = -l.forward();
    EXPECT_NEAR(shadeSH9(sh, toLight).g, 2.0f * 1.0625f, 1e-5f);
    EXPECT_NEAR(shadeSH9(sh, -toLight).g, 2.0f * 0.0625f, 1e-5f);
    const glm::vec3 side = glm::normalize(glm::cross(toLight, glm::vec3(0, 1, 0)));
    EXPECT_NEAR(shadeSH9(sh, side).g, 2.0f * 0.09375f, 1e-5f);
}

}  // namespace
}  // namespace varc::scene
