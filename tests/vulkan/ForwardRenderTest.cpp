// SPDX-License-Identifier: Apache-2.0
// The forward renderer on lavapipe: Unity's light rules observed in rendered pixels, and the
// validation scenes compared with the CPU reference (issue #5).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <functional>

#include "VulkanTestSupport.h"
#include "varc/image/Png.h"
#include "varc/reader/Pack.h"
#include "varc/reader/VariantRequests.h"
#include "varc/reference/ImageCompare.h"
#include "varc/reference/ReferenceRenderer.h"
#include "varc/reference/SceneTolerance.h"
#include "varc/render/ForwardRenderer.h"
#include "varc/scene/Scene.h"

namespace varc::render {
namespace {

constexpr const char* kSeedShader = "Custom/My First Lighting Shader";

scene::Object sphere(glm::vec3 position) {
    scene::Object object;
    object.mesh = scene::MeshKind::Sphere;
    object.transform.position = position;
    object.material.shader = kSeedShader;
    object.material.properties = {{"_Tint", glm::vec4(0.8f, 0.7f, 0.6f, 1.0f)},
                                  {"_MainTex", std::string("white")},
                                  {"_Metallic", 0.0f},
                                  {"_Smoothness", 0.3f}};
    return object;
}

scene::Light pointLight(glm::vec3 position, glm::vec3 color, float range) {
    scene::Light light;
    light.type = scene::LightType::Point;
    light.transform.position = position;
    light.color = color;
    light.range = range;
    return light;
}

// One sphere in front of the camera, black background, no ambient, HDR so sums are not clamped.
scene::Scene oneSphere() {
    scene::Scene scene;
    scene.camera.position = {0, 0, -2.5f};
    scene.camera.width = scene.camera.height = 64;
    scene.camera.hdr = true;
    scene.objects.push_back(sphere({0, 0, 0}));
    return scene;
}

// The largest R, G, B or A difference between two float images of one size.
float maxRgbaDifference(const image::Image& a, const image::Image& b) {
    float worst = 0;
    for (size_t i = 0; i < a.floats().size(); ++i)
        worst = std::max(worst, std::abs(a.floats()[i] - b.floats()[i]));
    return worst;
}

using ForwardRenderTest = testing::RendererTest<ForwardRenderer>;

TEST_F(ForwardRenderTest, APointLightOutOfRangeChangesNothing) {
    scene::Scene scene = oneSphere();
    scene.lights.push_back(pointLight({-1.0f, 1.0f, -1.0f}, glm::vec3(1.0f), 5.0f));
    RenderedFrame lit = render(scene);
    scene.lights.push_back(
        pointLight({30.0f, 0.0f, 0.0f}, glm::vec3(1.0f), 2.0f));  // 29.5 m from the sphere
    RenderedFrame withFarLight = render(scene);
    ASSERT_GT(testing::rgbSum(lit.image), 1.0f) << "the in-range light must light the sphere";
    EXPECT_EQ(maxRgbaDifference(lit.image, withFarLight.image), 0.0f);
    EXPECT_EQ(lit.draws, withFarLight.draws);
}

TEST_F(ForwardRenderTest, TwoPixelLightsAddUp) {
    scene::Scene first = oneSphere(), second = oneSphere(), both = oneSphere();
    scene::Light a = pointLight({-1.2f, 0.8f, -1.0f}, {1.0f, 0.5f, 0.2f}, 6.0f);
    scene::Light b = pointLight({1.2f, -0.4f, -1.0f}, {0.2f, 0.4f, 1.0f}, 6.0f);
    a.renderMode = b.renderMode = scene::LightRenderMode::Important;
    first.lights = {a};
    second.lights = {b};
    both.lights = {a, b};
    RenderedFrame imageA = render(first), imageB = render(second), imageAB = render(both);
    ASSERT_EQ(imageAB.draws, 3u) << "base pass plus one add pass per point light";
    float worst = 0;
    for (size_t i = 0; i < imageAB.image.floats().size(); i += 4) {
        for (size_t c = 0; c < 3; ++c) {
            float expected = imageA.image.floats()[i + c] + imageB.image.floats()[i + c];
            worst = std::max(worst, std::abs(imageAB.image.floats()[i + c] - expected));
        }
    }
    EXPECT_LT(worst, 2e-3f) << "half-float sums of two additive passes";
    EXPECT_GT(testing::rgbSum(imageA.image), 1.0f);
    EXPECT_GT(testing::rgbSum(imageB.image), 1.0f);
}

TEST_F(ForwardRenderTest, WithNoPixelLightsAPointLightStillLightsThroughVertexLights) {
    scene::Scene dark = oneSphere();
    dark.pixelLightCount = 0;
    scene::Scene lit = dark;
    lit.lights.push_back(pointLight({-1.0f, 1.0f, -1.5f}, glm::vec3(1.0f), 8.0f));
    RenderedFrame darkFrame = render(dark), litFrame = render(lit);
    ASSERT_EQ(litFrame.variants.size(), 1u) << "no add pass when pixel_light_count is 0";
    EXPECT_NE(litFrame.variants[0].find("VERTEXLIGHT_ON"), std::string::npos)
        << litFrame.variants[0];
    EXPECT_GT(testing::rgbSum(litFrame.image), testing::rgbSum(darkFrame.image) + 1.0f);
}

// Renderer::useVariantRequests: every draw's variant request is recorded, once per distinct
// request, and held variants are not misses.
TEST_F(ForwardRenderTest, VariantRequestsRecordEveryDraw) {
    scene::Scene scene = oneSphere();
    scene.objects.push_back(sphere({1.2f, 0, 0}));
    scene.lights.push_back(pointLight({-1.0f, 1.0f, -1.0f}, glm::vec3(1.0f), 5.0f));
    reader::VariantRequests requests;
    mRenderer->useVariantRequests(&requests, variants::SelectionPolicy::Strict);
    RenderedFrame frame = render(scene);
    mRenderer->useVariantRequests(nullptr, variants::SelectionPolicy::Closest);
    EXPECT_EQ(frame.draws, 4u);  // two objects, ForwardBase and one ForwardAdd each
    EXPECT_EQ(requests.requestCount(), 2u);
    EXPECT_TRUE(requests.misses().empty());
    const std::string log = requests.usageLog();
    EXPECT_NE(log.find(std::string("{\"shader\":\"") + kSeedShader +
                       "\",\"pass\":1,\"lightmode\":\"ForwardAdd\",\"keywords\":[\"POINT\"]}\n"),
              std::string::npos)
        << log;
}

TEST_F(ForwardRenderTest, UnknownShaderIsAClearError) {
    scene::Scene scene = oneSphere();
    scene.objects[0].material.shader = "Custom/Missing";
    auto frame = mRenderer->render(scene);
    ASSERT_FALSE(frame);
    EXPECT_NE(frame.error().detail.find("Custom/Missing"), std::string::npos)
        << frame.error().detail;
}

// Every validation scene matches the CPU reference within the tolerances.
// The camera and the light lie in the x = 0 plane, so mirroring the sphere in x must mirror the
// image: a mirrored object still shows its outside (Cull Back becomes Cull Front for it). With the
// inside faces shown instead, most of the sphere would differ.
TEST_F(ForwardRenderTest, AMirroredObjectShowsItsOutside) {
    scene::Scene scene = oneSphere();
    scene.lights.push_back(pointLight({0.0f, 1.0f, -1.5f}, glm::vec3(1.0f), 5.0f));
    RenderedFrame plain = render(scene);
    scene.objects[0].transform.scale = {-1.0f, 1.0f, 1.0f};
    RenderedFrame mirrored = render(scene);
    ASSERT_GT(testing::rgbSum(plain.image), 1.0f);
    const uint32_t w = plain.image.width(), h = plain.image.height();
    size_t differing = 0, covered = 0;
    for (uint32_t y = 0; y < h; ++y) {
        for (uint32_t x = 0; x < w; ++x) {
            const auto a = plain.image.pixelFloat(w - 1 - x, y);
            const auto b = mirrored.image.pixelFloat(x, y);
            covered += a[0] + a[1] + a[2] > 0.0f;
            float worst = 0.0f;
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(a[c] - b[c]));
            differing += worst > 2.0f / 255.0f;
        }
    }
    ASSERT_GT(covered, 250u);  // the sphere covers ~11 px of radius
    EXPECT_LT(differing, covered / 50) << differing << " of " << covered << " pixels differ";
}

TEST_F(ForwardRenderTest, ValidationScenesMatchTheCpuReference) {
    std::vector<std::string> scenes = testing::sceneFiles("forward");
    ASSERT_GE(scenes.size(), 5u);
    for (const std::string& path : scenes) {
        SCOPED_TRACE(path);
        auto scene = scene::loadScene(path);
        ASSERT_TRUE(scene) << scene.error().detail;
        RenderedFrame frame = render(*scene);
        auto expected = reference::renderReference(*scene);
        ASSERT_TRUE(expected) << expected.error().detail;
        reference::CompareResult result = reference::compareImages(
            frame.image, expected->color, expected->classes, reference::toleranceFor(*scene),
            expected->colorHigh.width() ? &expected->colorHigh : nullptr);
        EXPECT_TRUE(result.passed) << result.message;
        EXPECT_GT(result.interiorPixels, 100u) << "the scene must show lit objects";
    }
}

// The shadow scenes against a deliberately wrong reference: each mistake a shadow implementation
// can make must show as failing pixels (issue #11: a wrong bias, a missing fade, a flipped
// comparison).
TEST_F(ForwardRenderTest, ShadowMistakesInTheReferenceFail) {
    struct Mutation {
        const char* scene;
        const char* what;
        std::function<void(scene::Scene&, reference::ReferenceOptions&)> apply;
    };
    const Mutation mutations[] = {
        {"spot-shadow-hard.json", "flipped depth comparison",
         [](scene::Scene&, reference::ReferenceOptions& o) {
             o.editShadowMap = [](reference::ShadowMapReference& map) { map.flipCompareForTests(); };
         }},
        {"spot-shadow-hard.json", "no depth or normal bias (acne)",
         [](scene::Scene& s, reference::ReferenceOptions&) {
             for (scene::Light& light : s.lights) light.shadowBias = light.shadowNormalBias = 0.0f;
         }},
        {"spot-shadow-soft.json", "ten times the bias (peter-panning)",
         [](scene::Scene& s, reference::ReferenceOptions&) {
             for (scene::Light& light : s.lights) {
                 light.shadowBias *= 10.0f;
                 light.shadowNormalBias *= 10.0f;
             }
         }},
        {"spot-shadow-fade.json", "shadow-distance fade ignored",
         [](scene::Scene&, reference::ReferenceOptions& o) { o.ignoreShadowFade = true; }},
        {"spot-shadow-soft.json", "hard instead of soft",
         [](scene::Scene& s, reference::ReferenceOptions&) {
             for (scene::Light& light : s.lights) light.shadows = scene::ShadowType::Hard;
         }},
        {"point-shadow-hard.json", "flipped depth comparison in the cube",
         [](scene::Scene&, reference::ReferenceOptions& o) {
             o.editShadowMap = [](reference::ShadowMapReference& map) { map.flipCompareForTests(); };
         }},
        {"point-shadow-hard.json", "no bias (acne in the cube)",
         [](scene::Scene& s, reference::ReferenceOptions&) {
             for (scene::Light& light : s.lights) light.shadowBias = light.shadowNormalBias = 0.0f;
         }},
        {"directional-shadow-hard.json", "no directional shadow",
         [](scene::Scene& s, reference::ReferenceOptions&) {
             for (scene::Light& light : s.lights) light.shadows = scene::ShadowType::None;
         }},
        {"directional-shadow-cascades4.json", "no shadows from either directional light",
         [](scene::Scene& s, reference::ReferenceOptions&) {
             for (scene::Light& light : s.lights) light.shadows = scene::ShadowType::None;
         }},
        {"directional-shadow-cascades4.json", "one cascade instead of four",
         [](scene::Scene& s, reference::ReferenceOptions&) { s.shadowCascades = 1; }},
        {"directional-shadow-cascades2-soft.json", "hard instead of the 7x7 tent",
         [](scene::Scene& s, reference::ReferenceOptions&) {
             for (scene::Light& light : s.lights) light.shadows = scene::ShadowType::Hard;
         }},
        {"directional-shadow-cascades2-soft.json", "stable fit instead of close fit",
         [](scene::Scene& s, reference::ReferenceOptions&) { s.stableFit = true; }},
        {"point-shadow-soft.json", "hard instead of soft in the cube",
         [](scene::Scene& s, reference::ReferenceOptions&) {
             for (scene::Light& light : s.lights) light.shadows = scene::ShadowType::Hard;
         }},
        // Alpha-tested casters (Transparent/Cutout/*): the holes must show in every light's map.
        {"cutout-spot-shadow.json", "spot caster ignores _Cutoff",
         [](scene::Scene&, reference::ReferenceOptions& o) { o.ignoreCasterCutoff = true; }},
        {"cutout-point-shadow.json", "point caster ignores _Cutoff",
         [](scene::Scene&, reference::ReferenceOptions& o) { o.ignoreCasterCutoff = true; }},
        {"cutout-directional-shadow.json", "directional caster ignores _Cutoff",
         [](scene::Scene&, reference::ReferenceOptions& o) { o.ignoreCasterCutoff = true; }},
        {"cutout-spot-shadow.json", "the VertexLit object casts no shadow",
         [](scene::Scene& s, reference::ReferenceOptions&) {
             for (scene::Object& object : s.objects) {
                 if (object.material.shader == "Legacy Shaders/VertexLit")
                     object.transform.position.x += 5.0f;
             }
         }},
        {"fallback-casters-point.json", "Standard's _ALPHATEST_ON caster ignores _Cutoff",
         [](scene::Scene&, reference::ReferenceOptions& o) { o.ignoreCasterCutoff = true; }},
        {"fallback-casters-spot.json", "Standard's alpha-blended casters taken as opaque",
         [](scene::Scene& s, reference::ReferenceOptions&) {
             for (scene::Object& object : s.objects) object.material.keywords.clear();
         }},
        // Lightmaps (LIGHTING.md §8.7): what the lightmap variants change in these shaders.
        {"lightmaps-shadowmask-shadow-vertex.json", "lightmapped objects keep vertex lights and SH",
         [](scene::Scene& s, reference::ReferenceOptions&) {
             for (scene::Object& object : s.objects) {
                 object.lightmap.reset();
                 object.lightProbes.reset();
             }
         }},
        {"lightmaps-baked-indirect-noshadow-vertex.json", "every object samples SH",
         [](scene::Scene& s, reference::ReferenceOptions&) {
             for (scene::Object& object : s.objects) object.lightProbes = true;
         }},
        {"lightmaps-baked-indirect-noshadow-vertex.json", "no object samples SH",
         [](scene::Scene&, reference::ReferenceOptions& options) { options.lightProbeSh = false; }},
    };
    for (const Mutation& mutation : mutations) {
        SCOPED_TRACE(std::string(mutation.scene) + ": " + mutation.what);
        auto scene = scene::loadScene(testing::sceneFile("forward", mutation.scene));
        ASSERT_TRUE(scene) << scene.error().detail;
        RenderedFrame frame = render(*scene);
        scene::Scene wrongScene = *scene;
        reference::ReferenceOptions wrong;
        mutation.apply(wrongScene, wrong);
        auto expected = reference::renderReference(wrongScene, wrong);
        ASSERT_TRUE(expected) << expected.error().detail;
        reference::CompareResult result = reference::compareImages(
            frame.image, expected->color, expected->classes, reference::toleranceFor(*scene),
            expected->colorHigh.width() ? &expected->colorHigh : nullptr);
        EXPECT_FALSE(result.passed) << result.message;
        EXPECT_GT(result.failingPixels, 20u) << result.message;
    }
}

}  // namespace
}  // namespace varc::render

namespace varc::render {
namespace {

// A forward renderer over the helper pack (tests/vulkan/helpers): Test/LightmapProbe outputs the
// lightmaps its ForwardBase draw sampled.
class LightmapBindingTest : public testing::VulkanTest {
protected:
    void SetUp() override {
        VulkanTest::SetUp();
        if (HasFatalFailure()) return;
        auto pack = reader::Pack::open(VARC_TEST_PACK_DIR "/helpers.svpack");
        ASSERT_TRUE(pack) << pack.error().detail;
        mPack.emplace(std::move(*pack));
        auto renderer = ForwardRenderer::create(context(), {&*mPack});
        ASSERT_TRUE(renderer) << renderer.error().detail;
        mRenderer.emplace(std::move(*renderer));
    }
    void TearDown() override {
        mRenderer.reset();
        mPack.reset();
        VulkanTest::TearDown();
    }

    // The centre pixel of one lightmap-probe sphere facing the camera (its normal there is -z),
    // and the variant its ForwardBase draw used.
    std::pair<glm::vec4, std::string> centre(const scene::Scene& scene) {
        RenderedFrame frame = testing::frameOf(mRenderer->render(scene));
        if (frame.image.width() == 0 || frame.variants.empty()) {
            ADD_FAILURE() << "nothing rendered";
            return {};
        }
        const auto c = frame.image.pixelFloat(scene.camera.width / 2, scene.camera.height / 2);
        return {glm::vec4(c[0], c[1], c[2], c[3]), frame.variants.front()};
    }

    static scene::Scene probeScene(std::optional<scene::Lightmap> lightmap,
                                   scene::MixedLightingMode mode) {
        scene::Scene scene = oneSphere();
        scene.objects[0].material = {"Test/LightmapProbe", {}, "", {}};
        scene.objects[0].lightmap = std::move(lightmap);
        scene.mixedLighting = mode;
        return scene;
    }

    std::optional<reader::Pack> mPack;
    std::optional<ForwardRenderer> mRenderer;
};

void expectNear(const glm::vec4& actual, const glm::vec4& expected) {
    for (int c = 0; c < 4; ++c) {
        EXPECT_NEAR(actual[c], expected[c], 2e-3f + 2e-3f * std::abs(expected[c]))
            << "channel " << c;
    }
}

TEST_F(LightmapBindingTest, BakedLightmapIsBoundFullHdr) {
    scene::Lightmap lightmap;
    lightmap.baked = glm::vec3(1.5f, 0.5f, 0.25f);
    lightmap.scaleOffset = glm::vec4(0.5f, 0.5f, 0.25f, 0.25f);
    auto [pixel, variant] = centre(probeScene(lightmap, scene::MixedLightingMode::BakedIndirect));
    expectNear(pixel, glm::vec4(1.5f, 0.5f, 0.25f, 1.0f));
    EXPECT_NE(variant.find("LIGHTMAP_ON"), std::string::npos) << variant;
    EXPECT_EQ(variant.find("SHADOWMASK"), std::string::npos) << variant;
}

TEST_F(LightmapBindingTest, DirectionalRealtimeAndShadowmaskAreBound) {
    scene::Lightmap lightmap;
    lightmap.baked = glm::vec3(0.5f, 0.25f, 0.125f);
    lightmap.realtime = glm::vec3(0.25f);
    // Towards the camera, rebalancing 0.5: the half-Lambert term is 1 at the centre, so 2x.
    lightmap.directional = glm::vec4(0.0f, 0.0f, -1.0f, 0.5f);
    lightmap.shadowmask = glm::vec4(0.25f, 1.0f, 1.0f, 1.0f);
    auto [pixel, variant] = centre(probeScene(lightmap, scene::MixedLightingMode::Shadowmask));
    expectNear(pixel, glm::vec4(1.25f, 0.75f, 0.5f, 0.125f));
    for (const char* keyword : {"LIGHTMAP_ON", "DIRLIGHTMAP_COMBINED", "DYNAMICLIGHTMAP_ON",
                                "SHADOWS_SHADOWMASK", "LIGHTMAP_SHADOW_MIXING"}) {
        EXPECT_NE(variant.find(keyword), std::string::npos) << keyword << " in " << variant;
    }
}

// A PNG lightmap, read at uv1 * unity_LightmapST.xy + zw: with a zero scale the offset alone
// picks the texel (2 x 1: red, then blue), so a wrong ST or uv shows as the other colour.
TEST_F(LightmapBindingTest, PngLightmapIsReadAtTheScaledAndOffsetUv) {
    image::Image png(2, 1, image::PixelFormat::Rgba8);
    png.setPixel8(0, 0, {255, 0, 0, 255});
    png.setPixel8(1, 0, {0, 0, 255, 255});
    const std::string path = ::testing::TempDir() + "varc-lightmap-test.png";
    ASSERT_TRUE(writePng(path, png));
    image::Image mask(1, 1, image::PixelFormat::Rgba8);
    mask.setPixel8(0, 0, {64, 255, 255, 255});
    const std::string maskPath = ::testing::TempDir() + "varc-shadowmask-test.png";
    ASSERT_TRUE(writePng(maskPath, mask));
    scene::Lightmap lightmap;
    lightmap.baked = glm::vec3(1.0f);
    lightmap.bakedFile = path;
    lightmap.shadowmaskFile = maskPath;
    lightmap.scaleOffset = glm::vec4(0.0f, 0.0f, 0.75f, 0.5f);
    auto [blue, blueVariant] =
        centre(probeScene(lightmap, scene::MixedLightingMode::DistanceShadowmask));
    expectNear(blue, glm::vec4(0.0f, 0.0f, 1.0f, 64.0f / 255.0f));
    lightmap.scaleOffset = glm::vec4(0.0f, 0.0f, 0.25f, 0.5f);
    auto [red, redVariant] =
        centre(probeScene(lightmap, scene::MixedLightingMode::DistanceShadowmask));
    expectNear(red, glm::vec4(1.0f, 0.0f, 0.0f, 64.0f / 255.0f));
    EXPECT_NE(redVariant.find("SHADOWS_SHADOWMASK"), std::string::npos) << redVariant;
    std::remove(path.c_str());
    std::remove(maskPath.c_str());
}

TEST_F(LightmapBindingTest, SubtractiveModeMixesOnlyLightmappedObjects) {
    auto [pixel, variant] = centre(probeScene(std::nullopt, scene::MixedLightingMode::Subtractive));
    expectNear(pixel, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    EXPECT_EQ(variant.find("LIGHTMAP"), std::string::npos) << variant;
    scene::Lightmap lightmap;
    lightmap.baked = glm::vec3(0.5f);
    auto [mixed, mixedVariant] =
        centre(probeScene(lightmap, scene::MixedLightingMode::Subtractive));
    expectNear(mixed, glm::vec4(0.5f, 0.5f, 0.5f, 0.5f));
    EXPECT_NE(mixedVariant.find("LIGHTMAP_SHADOW_MIXING"), std::string::npos) << mixedVariant;
}

}  // namespace
}  // namespace varc::render
