// SPDX-License-Identifier: Apache-2.0
// Shading: BRDF values derived by hand from LIGHTING.md §2, vertex lights (§5), attenuation (§3).
#include <cmath>

#include <gtest/gtest.h>

#include "varc/reference/Shading.h"

namespace varc::reference {
namespace {

// n = l = v: nl = nv = nh = lh = 1, so the Burley factors are 1 (pow5(0) = 0), diffuseTerm = 1,
// V = 0.5 / (1 + 1) = 0.25, D = α²/(π (α²)²) = 1/(π α²), specularTerm = V·D·π = 0.25/α², F = F0.
// Smoothness 0.5: perceptual roughness 0.5, α = 0.25, α² = 0.0625, specularTerm = 4; F0 = 0.04.
TEST(Shading, BrdfFacingTheLight) {
    const SurfaceColors s = diffuseAndSpecularFromMetallic(glm::vec3(1.0f), 0.0f);
    EXPECT_NEAR(s.diffuse.r, 0.96f, 1e-6f);
    EXPECT_NEAR(s.specular.r, 0.04f, 1e-6f);
    const glm::vec3 n(0, 0, -1);
    const glm::vec3 c = brdfPbs(s, 0.5f, n, n, n, glm::vec3(0.5f), glm::vec3(0.0f), glm::vec3(0.0f));
    EXPECT_NEAR(c.g, 0.5f * (0.96f + 4.0f * 0.04f), 1e-4f);
}

TEST(Shading, BrdfMetallicTintsSpecular) {
    const SurfaceColors s = diffuseAndSpecularFromMetallic(glm::vec3(1.0f, 0.5f, 0.25f), 1.0f);
    EXPECT_EQ(s.diffuse, glm::vec3(0.0f));
    EXPECT_NEAR(s.specular.g, 0.5f, 1e-6f);
    EXPECT_NEAR(s.oneMinusReflectivity, 0.0f, 1e-6f);
}

// A light at grazing incidence (n·l = 0) leaves only the indirect diffuse c_d·I_d (I_s = 0).
TEST(Shading, BrdfIndirectOnlyWhenLightIsBehind) {
    const SurfaceColors s = diffuseAndSpecularFromMetallic(glm::vec3(0.5f), 0.0f);
    const glm::vec3 c = brdfPbs(s, 0.8f, {0, 1, 0}, glm::normalize(glm::vec3(0, 1, -1)), {0, -1, 0},
                                glm::vec3(3.0f), glm::vec3(0.2f), glm::vec3(0.0f));
    EXPECT_NEAR(c.r, 0.5f * 0.96f * 0.2f, 1e-6f);
}

// Light 2 m along the normal, range 10: atten 1/(1 + 4·25/100) = 0.5, n·l = 1.
TEST(Shading, Shade4PointLights) {
    scene::Scene scene;
    scene::Light l;
    l.type = scene::LightType::Point;
    l.transform.position = {0, 2, 0};
    l.range = 10.0f;
    l.color = {1.0f, 0.5f, 0.0f};
    l.intensity = 2.0f;
    scene.lights = {l, l};
    scene.lights[1].transform.position = {0, -2, 0};  // behind the surface: contributes 0
    const VertexLights v = vertexLightsFor(scene, {0, 1});
    EXPECT_EQ(v.attenSq.x, 0.25f);
    EXPECT_EQ(v.attenSq.z, 0.0f);  // unused slot
    const glm::vec3 c = shade4PointLights(v, glm::vec3(0.0f), {0, 1, 0});
    EXPECT_NEAR(c.r, 1.0f, 1e-6f);
    EXPECT_NEAR(c.g, 0.5f, 1e-6f);
    // From (2, 0, 0) with normal +y: light 0 is at 45° (n·l = √½) and d² = 8 (atten 1/3);
    // light 1 is below the surface.
    EXPECT_NEAR(shade4PointLights(v, {2, 0, 0}, {0, 1, 0}).r, 2.0f * std::sqrt(0.5f) / 3.0f, 1e-6f);
}

TEST(Shading, SpotAttenuationInsideOutsideBehind) {
    scene::Light l;
    l.type = scene::LightType::Spot;
    l.transform.position = {0, 4, 0};
    l.transform.rotationDegrees = {90, 0, 0};  // shines down
    l.range = 8.0f;
    l.spotAngle = 60.0f;
    auto pass = passLightFor(l);
    ASSERT_TRUE(pass.ok());
    EXPECT_EQ(pass->keyword, LightKeyword::Spot);
    const LightTextureSet textures;
    // On the axis 2 m below: cookie centre (1), falloff(4/64).
    EXPECT_NEAR(lightAttenuation(*pass, textures, {0, 2, 0}), scene::falloff(4.0f / 64.0f), 0.002f);
    // 2 m below and 2 m aside: 45° off the axis, outside the 30° half angle.
    EXPECT_EQ(lightAttenuation(*pass, textures, {2, 2, 0}), 0.0f);
    EXPECT_EQ(lightAttenuation(*pass, textures, {0, 5, 0}), 0.0f);  // behind the light
}

TEST(Shading, PointAndDirectionalAttenuation) {
    scene::Light l;
    l.type = scene::LightType::Point;
    l.transform.position = {1, 0, 0};
    l.range = 4.0f;
    const LightTextureSet textures;
    auto pass = passLightFor(l);
    ASSERT_TRUE(pass.ok());
    EXPECT_EQ(pass->worldSpaceLightPos, glm::vec4(1, 0, 0, 1));
    EXPECT_NEAR(lightAttenuation(*pass, textures, {1, 2, 0}), scene::falloff(0.25f), 0.001f);
    EXPECT_LT(lightAttenuation(*pass, textures, {1, 5, 0}), 1e-4f);  // beyond the range
    scene::Light d;
    d.transform.rotationDegrees = {90, 0, 0};
    auto dir = passLightFor(d);
    ASSERT_TRUE(dir.ok());
    EXPECT_NEAR(dir->worldSpaceLightPos.y, 1.0f, 1e-6f);  // towards the light: up
    EXPECT_EQ(dir->worldSpaceLightPos.w, 0.0f);
    EXPECT_EQ(lightAttenuation(*dir, textures, {3, 4, 5}), 1.0f);
    d.cookie = "stars";
    EXPECT_EQ(passLightFor(d).error().code, ErrorCode::Unsupported);
}

}  // namespace
}  // namespace varc::reference
