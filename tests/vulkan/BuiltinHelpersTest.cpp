// SPDX-License-Identifier: Apache-2.0
// Each built-in helper of varc's include library, run on lavapipe over a grid of positions and
// normals (tests/vulkan/helpers/BuiltinHelpers.shader), against its CPU formula from
// docs/LIGHTING.md as implemented by varc::reference (docs/LIGHTING.md §9.2): Shade4PointLights,
// ShadeSH9, UNITY_LIGHT_ATTENUATION per light type, and UNITY_BRDF_PBS.
// api-value-tested: Shade4PointLights ShadeSH9 UNITY_LIGHT_ATTENUATION UNITY_BRDF_PBS BRDF1_Unity_PBS
// api-value-tested: DiffuseAndSpecularFromMetallic
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <utility>
#include <glm/gtc/constants.hpp>

#include "QuadDrawTest.h"
#include "varc/reader/Pack.h"
#include "varc/reader/PassView.h"
#include "varc/reader/ShaderView.h"
#include "varc/reference/Shading.h"
#include "varc/render/BuiltinTextures.h"
#include "varc/render/DrawResources.h"
#include "varc/render/RenderStateResolver.h"
#include "varc/render/SceneValues.h"
#include "varc/render/VariantPipeline.h"
#include "varc/render/VertexLayout.h"
#include "varc/scene/ForwardLights.h"
#include "varc/vulkan/Buffer.h"
#include "varc/vulkan/RenderTarget.h"

namespace varc::render {
namespace {

constexpr uint32_t kSize = 48;
const glm::vec3 kBoxMin(-3.0f, -3.0f, -3.0f), kBoxMax(3.0f, 3.0f, 3.0f);
constexpr float kBoxZ = 0.4f;

// The same mapping as the shader, at the pixel centre.
glm::vec2 pixelUv(uint32_t x, uint32_t y) {
    return {(static_cast<float>(x) + 0.5f) / kSize, (static_cast<float>(y) + 0.5f) / kSize};
}
glm::vec3 worldPosition(glm::vec2 uv) { return glm::mix(kBoxMin, kBoxMax, glm::vec3(uv, kBoxZ)); }
glm::vec3 sphereNormal(glm::vec2 uv) {
    float longitude = uv.x * glm::two_pi<float>();
    float latitude = (uv.y - 0.5f) * glm::pi<float>();
    return {std::cos(latitude) * std::cos(longitude), std::sin(latitude),
            std::cos(latitude) * std::sin(longitude)};
}

class BuiltinHelpersTest : public testing::QuadDrawTest {
protected:
    BuiltinHelpersTest() : QuadDrawTest(kSize) {}

    // Draws the variant with |keywords| and returns the float image.
    image::Image run(const std::vector<std::string>& keywords, const ShaderValues& values,
                     const scene::Light* light) {
        reader::PassView pass = *mPack->findShader("Test/BuiltinHelpers")->pass(0);
        const BuiltinTextures& builtin = *mTextures;
        scene::LightType type = light ? light->type : scene::LightType::Directional;
        bool cookie = light && light->cookie != "none";
        TextureLookup textures = [&builtin, type, cookie](std::string_view name,
                                                          pack::ResourceDim dim) {
            if (auto texture = builtin.lightTexture(name, dim, type, cookie, false)) return texture;
            return builtin.named("white", dim);
        };
        return drawQuad(pass, keywords, values, textures);
    }

    // Compares every pixel's rgb (or only r when |channels| is 1) with |expected|(uv) within
    // |absolute| + |relative|·|expected|; reports the worst pixel.
    void expectMatches(const image::Image& image,
                       const std::function<glm::vec3(glm::vec2)>& expected, float absolute,
                       float relative, int channels = 3) {
        ASSERT_EQ(image.width(), kSize);
        float worst = 0;
        std::string where;
        float largest = 0;
        for (uint32_t y = 0; y < kSize; ++y) {
            for (uint32_t x = 0; x < kSize; ++x) {
                glm::vec3 want = expected(pixelUv(x, y));
                std::array<float, 4> got = image.pixelFloat(x, y);
                for (int c = 0; c < channels; ++c) {
                    float error = std::abs(got[static_cast<size_t>(c)] - want[c]) /
                                  (absolute + relative * std::abs(want[c]));
                    largest = std::max(largest, std::abs(want[c]));
                    if (error > worst) {
                        worst = error;
                        where = "pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                ") channel " + std::to_string(c) + ": GPU " +
                                std::to_string(got[static_cast<size_t>(c)]) + ", CPU " +
                                std::to_string(want[c]);
                    }
                }
            }
        }
        EXPECT_LE(worst, 1.0f) << "worst " << where;
        EXPECT_GT(largest, 0.05f)
            << "the expected values are all near zero: the test would prove nothing";
    }

    ShaderValues boxValues() const {
        ShaderValues values;
        values.set("_BoxMin", kBoxMin, 0.0f);
        values.set("_BoxMax", kBoxMax, 0.0f);
        values.set("_BoxZ", kBoxZ);
        return values;
    }

};

scene::Light makeLight(scene::LightType type, const std::string& cookie) {
    scene::Light light;
    light.type = type;
    light.transform.position = {0.5f, 0.8f, -2.2f};  // 1.6 m behind the sampled plane z = -0.6
    light.transform.rotationDegrees = {20.0f, 35.0f, 0.0f};
    light.range = 4.0f;
    light.spotAngle = 70.0f;
    light.cookie = cookie;
    light.cookieSize = 2.0f;
    return light;
}

// Unity matches default texture names without regard to case: `_Tex ("Tex", 2D) = "Gray" {}`
// is the gray texture (a corpus shader, RealisticShader, names it so), an unknown name is none.
TEST_F(BuiltinHelpersTest, DefaultTextureNamesIgnoreAsciiCase) {
    const BuiltinTextures& builtin = *mTextures;
    for (const auto& [lower, other] : {std::pair{"gray", "Gray"}, std::pair{"white", "WHITE"},
                                       std::pair{"bump", "Bump"}}) {
        auto expected = builtin.named(lower, pack::ResourceDim::Dim2D);
        auto got = builtin.named(other, pack::ResourceDim::Dim2D);
        ASSERT_TRUE(expected && got) << other;
        EXPECT_EQ(got->view, expected->view) << other;
    }
    EXPECT_NE(builtin.named("Gray", pack::ResourceDim::Dim2D)->view,
              builtin.named("white", pack::ResourceDim::Dim2D)->view);
    EXPECT_FALSE(builtin.named("Grayish", pack::ResourceDim::Dim2D));
    EXPECT_TRUE(builtin.named("White", pack::ResourceDim::Cube));
}

// A Cube property whose default is "" takes Unity's texture for an empty name, gray (the
// renderer passes "gray"): a gray cube, not the white one (a corpus shader, litTransformable,
// declares `_CustomSkybox ("...", Cube) = "" {}`).
TEST_F(BuiltinHelpersTest, AGrayCubeStandsForAnEmptyCubeDefault) {
    const BuiltinTextures& builtin = *mTextures;
    auto gray = builtin.named("Gray", pack::ResourceDim::Cube);
    auto white = builtin.named("white", pack::ResourceDim::Cube);
    ASSERT_TRUE(gray && white);
    EXPECT_NE(gray->view, white->view);
    EXPECT_EQ(builtin.named("grey", pack::ResourceDim::Cube)->view, gray->view);
    EXPECT_FALSE(builtin.named("bump", pack::ResourceDim::Cube));
}

struct AttenuationCase {
    const char* keyword;
    scene::LightType type;
    const char* cookie;
    float tolerance;  // absolute
};

TEST_F(BuiltinHelpersTest, LightAttenuationMatchesPerLightType) {
    // The falloff table is 16-bit: the GPU's 8-bit sub-texel filter weights move a sample by at
    // most 1/256 of one texel step. Cookies are 8-bit: up to 1.5/255 between the GPU's filter and
    // exact bilinear weights (and the reference does not filter across cube faces).
    constexpr float kTable = 1e-3f, kCookie = 1.5f / 255.0f;
    const AttenuationCase cases[] = {
        {"POINT", scene::LightType::Point, "none", kTable},
        {"SPOT", scene::LightType::Spot, "default", kCookie},
        {"POINT_COOKIE", scene::LightType::Point, "default", kCookie},
        {"DIRECTIONAL_COOKIE", scene::LightType::Directional, "default", kCookie},
        {"DIRECTIONAL", scene::LightType::Directional, "none", 1e-6f}};
    reference::LightTextureSet textures;
    for (const AttenuationCase& c : cases) {
        SCOPED_TRACE(c.keyword);
        scene::Light light = makeLight(c.type, c.cookie);
        ShaderValues values = forwardLightValues(&light);
        values.merge(boxValues());
        auto passLight = reference::passLightFor(light);
        ASSERT_TRUE(passLight) << passLight.error().detail;
        image::Image image = run({"HELPER_ATTENUATION", c.keyword}, values, &light);
        expectMatches(
            image,
            [&](glm::vec2 uv) {
                return glm::vec3(
                    reference::lightAttenuation(*passLight, textures, worldPosition(uv)));
            },
            c.tolerance, 0.0f, 1);
    }
}

TEST_F(BuiltinHelpersTest, Shade4PointLightsMatches) {
    scene::Scene scene;
    std::vector<int> indices;
    const glm::vec3 colors[] = {
        {1.0f, 0.2f, 0.1f}, {0.1f, 1.0f, 0.3f}, {0.2f, 0.3f, 1.0f}, {0.8f, 0.8f, 0.2f}};
    for (int i = 0; i < 4; ++i) {
        scene::Light light = makeLight(scene::LightType::Point, "none");
        light.transform.position = {static_cast<float>(i) - 1.5f, 0.5f * static_cast<float>(i % 2),
                                    -1.0f};
        light.color = colors[i];
        light.range = 2.0f + static_cast<float>(i);
        scene.lights.push_back(light);
        indices.push_back(i);
    }
    reference::VertexLights lights = reference::vertexLightsFor(scene, indices);
    ShaderValues values = boxValues();
    values.set("unity_4LightPosX0", lights.posX);
    values.set("unity_4LightPosY0", lights.posY);
    values.set("unity_4LightPosZ0", lights.posZ);
    values.set("unity_4LightAtten0", lights.attenSq);
    std::vector<glm::vec4> lightColors(8, glm::vec4(0.0f));
    for (size_t i = 0; i < 4; ++i) lightColors[i] = glm::vec4(lights.colors[i], 1.0f);
    values.setArray("unity_LightColor", lightColors);
    image::Image image = run({"HELPER_SHADE4", "POINT"}, values, nullptr);
    expectMatches(
        image,
        [&](glm::vec2 uv) {
            return reference::shade4PointLights(lights, worldPosition(uv), sphereNormal(uv));
        },
        1e-4f, 1e-4f);
}

TEST_F(BuiltinHelpersTest, ShadeSH9Matches) {
    scene::Scene scene;
    scene.ambient = {0.1f, 0.15f, 0.2f};
    scene::Light key = makeLight(scene::LightType::Directional, "none");
    key.color = {1.0f, 0.8f, 0.6f};
    scene::Light fill = makeLight(scene::LightType::Point, "none");
    fill.color = {0.2f, 0.4f, 1.0f};
    fill.range = 10.0f;
    scene.lights = {key, fill};
    scene::Object object;
    std::array<glm::vec4, 7> sh = scene::packedSH(scene, object, {0, 1});
    ShaderValues values = boxValues();
    const char* names[] = {"unity_SHAr", "unity_SHAg", "unity_SHAb", "unity_SHBr",
                           "unity_SHBg", "unity_SHBb", "unity_SHC"};
    for (size_t i = 0; i < sh.size(); ++i) values.set(names[i], sh[i]);
    image::Image image = run({"HELPER_SH9", "POINT"}, values, nullptr);
    expectMatches(
        image, [&](glm::vec2 uv) { return scene::shadeSH9(sh, sphereNormal(uv)); }, 1e-4f, 1e-4f);
}

TEST_F(BuiltinHelpersTest, PhysicallyBasedBrdfMatches) {
    const glm::vec3 lightDirection = glm::normalize(glm::vec3(0.3f, 0.8f, -0.5f));
    const glm::vec3 viewDirection = glm::normalize(glm::vec3(-0.2f, 0.4f, -1.0f));
    const glm::vec3 lightColor(1.0f, 0.9f, 0.8f);
    for (float metallic : {0.0f, 1.0f}) {
        for (float smoothness : {0.2f, 0.8f}) {
            SCOPED_TRACE("metallic " + std::to_string(metallic) + " smoothness " +
                         std::to_string(smoothness));
            glm::vec3 albedo(0.8f, 0.5f, 0.3f);
            ShaderValues values = boxValues();
            values.set("_Albedo", albedo, metallic);
            values.set("_Smoothness", smoothness);
            values.set("_ViewDir", viewDirection, 0.0f);
            values.set("_LightColor0", lightColor, 1.0f);
            values.set("_WorldSpaceLightPos0", lightDirection, 0.0f);
            image::Image image = run({"HELPER_BRDF", "POINT"}, values, nullptr);
            reference::SurfaceColors surface =
                reference::diffuseAndSpecularFromMetallic(albedo, metallic);
            expectMatches(
                image,
                [&](glm::vec2 uv) {
                    return reference::brdfPbs(surface, smoothness, sphereNormal(uv), viewDirection,
                                              lightDirection, lightColor, glm::vec3(0.0f),
                                              glm::vec3(0.0f));
                },
                2e-4f, 2e-3f);
        }
    }
}

}  // namespace
}  // namespace varc::render
