// SPDX-License-Identifier: Apache-2.0
// Falloff table, default cookies, cube face selection and unity_WorldToLight (SHADER_ABI.md §5, §6).
#include <cmath>

#include <gtest/gtest.h>

#include "varc/scene/LightTextures.h"

namespace varc::scene {
namespace {

TEST(LightTextures, FalloffValues) {
    EXPECT_FLOAT_EQ(falloff(0.0f), 1.0f);
    EXPECT_NEAR(falloff(0.64f), 1.0f / 17.0f, 1e-6f);           // fade starts at 80 % of the range
    EXPECT_NEAR(falloff(0.82f), 0.5f / 21.5f, 1e-6f);           // half way through the fade
    EXPECT_EQ(falloff(1.0f), 0.0f);
    EXPECT_EQ(falloff(1.5f), 0.0f);
}

TEST(LightTextures, FalloffTableHoldsTexelCentres) {
    const std::vector<uint16_t> table = falloffTable();
    ASSERT_EQ(table.size(), 1024u);
    for (size_t i = 0; i < table.size(); i += 37) {
        const double t = (static_cast<double>(i) + 0.5) / 1024.0;
        const double f = 1.0 / (1.0 + 25.0 * t) * std::min(1.0, std::max(0.0, (1.0 - t) / 0.36));
        EXPECT_NEAR(table[i], f * 65535.0, 0.51) << i;
    }
    EXPECT_EQ(table[0], 64745);  // 65535 / (1 + 25 * 0.5/1024) = 64744.6
}

TEST(LightTextures, TableSamplingIsLinearAndClamped) {
    const std::vector<uint16_t> table = falloffTable();
    // At a texel centre the sample is the texel; half way it is the mean.
    EXPECT_FLOAT_EQ(sampleFalloffTable(table, 10.5f / 1024.0f), table[10] / 65535.0f);
    EXPECT_NEAR(sampleFalloffTable(table, 11.0f / 1024.0f), (table[10] + table[11]) / 2.0f / 65535.0f, 1e-6f);
    EXPECT_FLOAT_EQ(sampleFalloffTable(table, 0.0f), table[0] / 65535.0f);
    EXPECT_FLOAT_EQ(sampleFalloffTable(table, 3.0f), table[1023] / 65535.0f);
    // Within 0.3 % of the analytic curve away from the first half texel (LIGHTING.md §4).
    for (float t = 0.01f; t < 0.6f; t += 0.013f) {
        EXPECT_NEAR(sampleFalloffTable(table, t), falloff(t), 0.003f * falloff(t)) << t;
    }
}

TEST(LightTextures, DefaultSpotCookieIsASoftDisc) {
    const CookieImage c = defaultSpotCookie();
    ASSERT_EQ(c.width, 128u);
    ASSERT_EQ(c.rgba.size(), 128u * 128u * 4u);
    auto alpha = [&](uint32_t x, uint32_t y) { return c.rgba[4 * (y * 128 + x) + 3]; };
    EXPECT_EQ(alpha(64, 64), 255);
    EXPECT_EQ(alpha(0, 0), 0);
    // The formula gives 10/255 at border texel (64, 0) (r = 0.4961); the border ring is forced to
    // 0 so that clamp-to-edge sampling outside the cone returns 0.
    for (uint32_t i = 0; i < 128; ++i) {
        EXPECT_EQ(alpha(i, 0), 0);
        EXPECT_EQ(alpha(127, i), 0);
    }
    EXPECT_EQ(alpha(64, 1), 30);  // r = hypot(0.5, 62.5)/128 = 0.48830: 255 * 5 (1 - 2r) = 29.84
    // Texel (64, 10): r = |(64.5, 10.5)/128 - 0.5| = 0.418 -> 5 (1 - 0.836) = 0.82.
    EXPECT_NEAR(alpha(64, 10), 255.0 * 5.0 * (1.0 - 2.0 * std::hypot(0.5 / 128.0, 53.5 / 128.0)), 0.6);
    EXPECT_EQ(c.rgba[0], 255);
}

TEST(LightTextures, DefaultCookieShapes) {
    const CookieImage d = defaultDirectionalCookie();
    EXPECT_EQ(d.layers, 1u);
    EXPECT_EQ(d.rgba.size(), size_t{d.width} * d.height * 4);
    const CookieImage p = defaultPointCookie();
    EXPECT_EQ(p.layers, 6u);
    EXPECT_EQ(p.width, p.height);
    EXPECT_EQ(p.rgba.size(), size_t{p.width} * p.height * 24);
    // +X face centre looks along +x (alpha 1), +Y face centre along +y (alpha 0).
    const size_t centre = (p.width / 2) * p.width + p.width / 2;
    EXPECT_GE(p.rgba[4 * centre + 3], 250);
    EXPECT_LE(p.rgba[4 * (2 * p.width * p.height + centre) + 3], 5);
}

// Vulkan's table: +X: s = -z/|x|, t = -y/|x|; +Y: s = x/|y|, t = z/|y|; -Z: s = -x/|z|, t = -y/|z|.
TEST(LightTextures, CubeFaceSelectionFollowsVulkan) {
    CubeCoord c = cubeFaceCoord({1.0f, 0.5f, 0.0f});
    EXPECT_EQ(c.face, 0);
    EXPECT_NEAR(c.st.x, 0.5f, 1e-6f);
    EXPECT_NEAR(c.st.y, 0.25f, 1e-6f);
    c = cubeFaceCoord({0.5f, 2.0f, -1.0f});
    EXPECT_EQ(c.face, 2);
    EXPECT_NEAR(c.st.x, 0.625f, 1e-6f);
    EXPECT_NEAR(c.st.y, 0.25f, 1e-6f);
    c = cubeFaceCoord({0.5f, 0.0f, -1.0f});
    EXPECT_EQ(c.face, 5);
    EXPECT_NEAR(c.st.x, 0.25f, 1e-6f);
    for (int face = 0; face < 6; ++face) {
        const CubeCoord back = cubeFaceCoord(cubeFaceDirection(face, {0.3f, 0.8f}));
        EXPECT_EQ(back.face, face);
        EXPECT_NEAR(back.st.x, 0.3f, 1e-6f);
        EXPECT_NEAR(back.st.y, 0.8f, 1e-6f);
    }
}

TEST(LightTextures, PointWorldToLightScalesRangeToOne) {
    Light l;
    l.type = LightType::Point;
    l.transform.position = {1, 2, 3};
    l.transform.rotationDegrees = {10, 20, 30};
    l.range = 2.0f;
    const glm::mat4 m = worldToLight(l, false);
    const glm::vec4 lc = m * glm::vec4(glm::vec3(1, 2, 3) + glm::normalize(glm::vec3(1, -2, 0.5f)) * 2.0f, 1);
    EXPECT_NEAR(glm::dot(glm::vec3(lc), glm::vec3(lc)), 1.0f, 1e-5f);
    EXPECT_NEAR(lc.w, 1.0f, 1e-6f);
}

TEST(LightTextures, SpotWorldToLightConventions) {
    Light l;
    l.type = LightType::Spot;
    l.transform.position = {0, 3, 0};
    l.transform.rotationDegrees = {90, 0, 0};  // shines down -y; local +x stays world +x
    l.range = 6.0f;
    l.spotAngle = 60.0f;
    const float t = std::tan(glm::radians(30.0f));
    // On the axis 2 m below: uv (0.5, 0.5); on the cone edge along local +x: u = 1.
    const glm::vec4 axis(0, 1, 0, 1), edge(2 * t, 1, 0, 1);
    const glm::mat4 fwd = worldToLight(l, false);
    glm::vec4 lc = fwd * axis;
    EXPECT_GT(lc.z, 0.0f);
    EXPECT_NEAR(lc.x / lc.w + 0.5f, 0.5f, 1e-6f);
    EXPECT_NEAR(glm::dot(glm::vec3(lc), glm::vec3(lc)), 4.0f / 36.0f, 1e-6f);
    lc = fwd * edge;
    EXPECT_NEAR(lc.x / lc.w + 0.5f, 1.0f, 1e-5f);
    EXPECT_NEAR(lc.y / lc.w + 0.5f, 0.5f, 1e-5f);
    const glm::mat4 deferred = worldToLight(l, true);
    lc = deferred * edge;
    EXPECT_LT(lc.w, 0.0f);
    EXPECT_NEAR(lc.x / lc.w, 1.0f, 1e-5f);
    EXPECT_NEAR(lc.y / lc.w, 0.5f, 1e-5f);
    EXPECT_LT((fwd * glm::vec4(0, 4, 0, 1)).z, 0.0f);  // behind the light
}

TEST(LightTextures, DirectionalCookieMatrixTilesBySize) {
    Light l;
    l.cookie = "default";
    l.cookieSize = 4.0f;
    const glm::mat4 m = worldToLight(l, false);  // no rotation: light space = world
    const glm::vec4 lc = m * glm::vec4(1, -2, 7, 1);
    EXPECT_NEAR(lc.x, 1.0f / 4.0f + 0.5f, 1e-6f);
    EXPECT_NEAR(lc.y, -2.0f / 4.0f + 0.5f, 1e-6f);
    l.cookie = "none";
    EXPECT_EQ(worldToLight(l, false), glm::mat4(1.0f));
}

}  // namespace
}  // namespace varc::scene
