// SPDX-License-Identifier: Apache-2.0
// The deferred renderer on lavapipe (issue #6): the stencil-masked background, lights adding up in
// the light buffer, HDR and LDR agreeing up to the LDR encoding, and the deferred validation
// scenes compared with the CPU reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "VulkanTestSupport.h"
#include "varc/reader/Pack.h"
#include "varc/reference/DeferredReference.h"
#include "varc/reference/ImageCompare.h"
#include "varc/reference/ReferenceRenderer.h"
#include "varc/reference/SceneTolerance.h"
#include "varc/render/DeferredRenderer.h"
#include "varc/render/ForwardRenderer.h"
#include "varc/scene/Scene.h"

namespace varc::render {
namespace {

scene::Object sphere(glm::vec3 position) {
    scene::Object object;
    object.mesh = scene::MeshKind::Sphere;
    object.transform.position = position;
    object.material.shader = "varc/DeferredGBuffer";
    object.material.properties = {{"_Color", glm::vec4(0.8f, 0.7f, 0.6f, 1.0f)},
                                  {"_MainTex", std::string("white")},
                                  {"_Metallic", 0.0f},
                                  {"_Smoothness", 0.3f}};
    return object;
}

scene::Light light(scene::LightType type, glm::vec3 position, float intensity) {
    scene::Light l;
    l.type = type;
    l.transform.position = position;
    l.transform.rotationDegrees = {40.0f, 20.0f, 0.0f};
    l.intensity = intensity;
    l.range = 5.0f;
    return l;
}

// One sphere in front of the camera, no ambient, a visible background colour.
scene::Scene oneSphere(bool hdr) {
    scene::Scene scene;
    scene.camera.position = {0, 0, -2.5f};
    scene.camera.width = scene.camera.height = 64;
    scene.camera.hdr = hdr;
    scene.camera.path = scene::RenderPath::Deferred;
    scene.camera.background = {0.2f, 0.4f, 0.6f, 1.0f};
    scene.ambient = glm::vec3(0.0f);
    scene.objects.push_back(sphere({0, 0, 0}));
    return scene;
}

using DeferredRenderTest = testing::RendererTest<DeferredRenderer>;

// The light quads cover the whole screen; the stencil bits of the G-buffer pass keep them (and
// the LDR decode) off the background.
TEST_F(DeferredRenderTest, TheStencilMaskKeepsLightsOffTheBackground) {
    for (bool hdr : {true, false}) {
        SCOPED_TRACE(hdr ? "HDR" : "LDR");
        scene::Scene scene = oneSphere(hdr);
        scene.lights.push_back(light(scene::LightType::Directional, {}, 2.0f));
        RenderedFrame frame = render(scene);
        ASSERT_EQ(frame.image.width(), 64u);
        std::array<float, 4> corner = frame.image.pixelFloat(0, 0);
        EXPECT_NEAR(corner[0], 0.2f, 1e-3f);
        EXPECT_NEAR(corner[1], 0.4f, 1e-3f);
        EXPECT_NEAR(corner[2], 0.6f, 1e-3f);
        std::array<float, 4> centre = frame.image.pixelFloat(32, 32);
        EXPECT_GT(centre[0], 0.05f) << "the light must reach the sphere";
        EXPECT_EQ(frame.draws, hdr ? 2u : 3u) << "G-buffer, one light, and the LDR decode";
    }
}

// A light whose range ends before the sphere adds nothing visible. Drawn as a full-screen quad it
// is not masked by a volume: the falloff table's last texel (clamp to edge) is f(1023.5/1024)
// ≈ 5e-5, so HDR gains up to ~0.01 LSB; LDR rounds exp2(−5e-5) to 255, × 1 = exactly nothing.
TEST_F(DeferredRenderTest, APointLightOutOfRangeChangesNothing) {
    for (bool hdr : {true, false}) {
        SCOPED_TRACE(hdr ? "HDR" : "LDR");
        scene::Scene scene = oneSphere(hdr);
        scene.lights.push_back(light(scene::LightType::Point, {-1.0f, 1.0f, -1.0f}, 1.0f));
        RenderedFrame lit = render(scene);
        scene.lights.push_back(light(scene::LightType::Point, {30.0f, 0.0f, 0.0f}, 1.0f));
        RenderedFrame withFarLight = render(scene);
        ASSERT_GT(testing::rgbSum(lit.image), 20.0f) << "the in-range light must light the sphere";
        EXPECT_LE(testing::maxRgbDifference(lit.image, withFarLight.image), hdr ? 1e-4f : 0.0f);
    }
}

// In HDR the light buffer sums the lights: A + B = (A) + (B) − (no light) up to half rounding.
TEST_F(DeferredRenderTest, LightsAddUpInTheHdrLightBuffer) {
    scene::Scene none = oneSphere(true);
    scene::Scene a = none, b = none, both = none;
    scene::Light point = light(scene::LightType::Point, {-1.0f, 1.0f, -1.0f}, 1.0f);
    scene::Light spot = light(scene::LightType::Spot, {0.5f, 1.5f, -1.5f}, 2.0f);
    spot.transform.rotationDegrees = {35.0f, -15.0f, 0.0f};
    spot.spotAngle = 60.0f;
    a.lights = {point};
    b.lights = {spot};
    both.lights = {point, spot};
    image::Image imageNone = render(none).image, imageA = render(a).image, imageB = render(b).image;
    image::Image imageBoth = render(both).image;
    ASSERT_GT(testing::rgbSum(imageA), testing::rgbSum(imageNone) + 10.0f);
    ASSERT_GT(testing::rgbSum(imageB), testing::rgbSum(imageNone) + 10.0f);
    float worst = 0;
    for (size_t i = 0; i < imageBoth.floats().size(); ++i) {
        float expected = imageA.floats()[i] + imageB.floats()[i] - imageNone.floats()[i];
        worst = std::max(
            worst, std::abs(imageBoth.floats()[i] - expected) / std::max(1.0f, std::abs(expected)));
    }
    EXPECT_LT(worst, 2e-3f);
}

// LDR stores exp2(−c) in 8 bits and decodes it: below saturation it agrees with HDR to a few LSB.
TEST_F(DeferredRenderTest, LdrAgreesWithHdrUpToTheEncoding) {
    scene::Scene hdr = oneSphere(true);
    hdr.lights.push_back(light(scene::LightType::Directional, {}, 0.6f));
    scene::Scene ldr = hdr;
    ldr.camera.hdr = false;
    image::Image imageHdr = render(hdr).image, imageLdr = render(ldr).image;
    ASSERT_TRUE(imageHdr.isFloat());
    ASSERT_FALSE(imageLdr.isFloat());
    ASSERT_GT(testing::rgbSum(imageLdr), 20.0f);
    EXPECT_LE(testing::maxRgbDifference(imageHdr.toRgba8(image::Tonemap::Clamp), imageLdr),
              4.0f / 255.0f);
}

TEST_F(DeferredRenderTest, AnObjectWithoutADeferredPassIsAClearError) {
    scene::Scene scene = oneSphere(true);
    scene.objects[0].material.shader = "varc/SimpleDiffuse";
    auto frame = mRenderer->render(scene);
    ASSERT_FALSE(frame);
    EXPECT_NE(frame.error().detail.find("no Deferred pass"), std::string::npos)
        << frame.error().detail;
}

// The deferred tolerances (6 LSB in LDR) still catch a real error: the reference of the scene
// without its point light, or with a directional light turned 10 degrees, must not pass.
TEST_F(DeferredRenderTest, TheToleranceCatchesAMissingOrMovedLight) {
    for (const char* name : {"point-ldr.json", "point-hdr.json"}) {
        SCOPED_TRACE(name);
        auto scene = scene::loadScene(std::string(VARC_TEST_SCENE_DIR "/deferred/") + name);
        ASSERT_TRUE(scene) << scene.error().detail;
        RenderedFrame frame = render(*scene);
        reference::Tolerance tolerance = reference::toleranceFor(*scene);
        scene::Scene missing = *scene;
        missing.lights.pop_back();
        scene::Scene moved = *scene;
        moved.lights.front().transform.rotationDegrees.x += 10.0f;
        for (const scene::Scene* wrong : {&missing, &moved}) {
            auto expected = reference::renderDeferredReference(*wrong);
            ASSERT_TRUE(expected) << expected.error().detail;
            EXPECT_FALSE(
                reference::compareImages(frame.image, expected->color, expected->classes, tolerance)
                    .passed);
        }
    }
}

// The same scene drawn forward (varc/Forward: base pass + one add pass per light) and deferred
// (varc/DeferredGBuffer + varc/DeferredLight) agrees within 2 LSB per pixel and 0.25 LSB on
// average (HDR, values up to ~1): the deferred G-buffer stores the diffuse and specular colours as
// 8-bit sRGB (one step is ≤ 1 % of the value); the rest is the same math in the same precision.
TEST_F(DeferredRenderTest, ForwardAndDeferredRendersOfOneSceneAgree) {
    auto deferredScene = scene::loadScene(VARC_TEST_SCENE_DIR "/deferred/mixed-hdr.json");
    ASSERT_TRUE(deferredScene) << deferredScene.error().detail;
    deferredScene->objects[2].material.properties.erase("_EmissionColor");
    scene::Scene forwardScene = *deferredScene;
    forwardScene.camera.path = scene::RenderPath::Forward;
    for (scene::Object& object : forwardScene.objects) object.material.shader = "varc/Forward";
    for (scene::Light& l : forwardScene.lights) l.renderMode = scene::LightRenderMode::Important;
    auto forwardRenderer = ForwardRenderer::create(context(), {&*mPack});
    ASSERT_TRUE(forwardRenderer) << forwardRenderer.error().detail;
    auto forward = forwardRenderer->render(forwardScene);
    ASSERT_TRUE(forward) << forward.error().detail;
    RenderedFrame deferred = render(*deferredScene);
    auto classes = reference::renderDeferredReference(*deferredScene);
    ASSERT_TRUE(classes) << classes.error().detail;
    reference::Tolerance tolerance;
    tolerance.interiorLsb = tolerance.edgeLsb = 2.0f;  // measured: max 0.44, mean -0.09 LSB
    reference::CompareResult result =
        reference::compareImages(deferred.image, forward->image, classes->classes, tolerance);
    EXPECT_TRUE(result.passed) << result.message;
    EXPECT_GT(result.maxErrorLsb, 0.0f) << "two different paths cannot agree bit for bit";
    EXPECT_GT(forward->draws, 6u) << "every light must draw per pixel in the forward render";
}

// Every deferred validation scene (HDR and LDR; directional, point, spot; with and without
// cookies) matches the CPU reference within the tolerances.
TEST_F(DeferredRenderTest, ValidationScenesMatchTheCpuReference) {
    std::vector<std::string> scenes = testing::sceneFiles("deferred");
    ASSERT_GE(scenes.size(), 10u);
    for (const std::string& path : scenes) {
        SCOPED_TRACE(path);
        auto scene = scene::loadScene(path);
        ASSERT_TRUE(scene) << scene.error().detail;
        RenderedFrame frame = render(*scene);
        auto expected = reference::renderDeferredReference(*scene);
        ASSERT_TRUE(expected) << expected.error().detail;
        reference::CompareResult result = reference::compareImages(
            frame.image, expected->color, expected->classes, reference::toleranceFor(*scene),
            expected->colorHigh.width() ? &expected->colorHigh : nullptr);
        EXPECT_TRUE(result.passed) << result.message;
        EXPECT_GT(result.interiorPixels, 100u) << "the scene must show lit objects";
    }
}

// The deferred light pass samples the spot light's shadow map, the point light's cube and the
// directional lights' screen masks: a reference without the shadows, or with another strength,
// fails each shadow scene.
TEST_F(DeferredRenderTest, ShadowMistakesInTheReferenceFail) {
    for (const char* name :
         {"spot-shadow-hdr.json", "directional-shadow-hdr.json", "point-shadow-ldr.json"}) {
        SCOPED_TRACE(name);
        auto scene = scene::loadScene(std::string(VARC_TEST_SCENE_DIR "/deferred/") + name);
        ASSERT_TRUE(scene) << scene.error().detail;
        RenderedFrame frame = render(*scene);
        scene::Scene unshadowed = *scene;
        for (scene::Light& light : unshadowed.lights) light.shadows = scene::ShadowType::None;
        scene::Scene strong = *scene;
        for (scene::Light& light : strong.lights) light.shadowStrength = 0.5f;
        for (const scene::Scene* wrong : {&unshadowed, &strong}) {
            auto expected = reference::renderDeferredReference(*wrong);
            ASSERT_TRUE(expected) << expected.error().detail;
            reference::CompareResult result = reference::compareImages(
                frame.image, expected->color, expected->classes, reference::toleranceFor(*scene),
                expected->colorHigh.width() ? &expected->colorHigh : nullptr);
            EXPECT_FALSE(result.passed) << result.message;
            EXPECT_GT(result.failingPixels, 20u) << result.message;
        }
    }
}

// A shadowed spot light drawn forward and deferred: the same shadow map (the same casters from
// the same light camera) read at the same world positions, so the two agree as the unshadowed
// scenes do (2 LSB), except where a shadow tap straddles its comparison: there the CPU reference
// allows any value between the two outcomes, and so does this test.
TEST_F(DeferredRenderTest, ForwardAndDeferredShadowedRendersAgree) {
    auto deferredScene = scene::loadScene(VARC_TEST_SCENE_DIR "/deferred/spot-shadow-hdr.json");
    ASSERT_TRUE(deferredScene) << deferredScene.error().detail;
    scene::Scene forwardScene = *deferredScene;
    forwardScene.camera.path = scene::RenderPath::Forward;
    for (scene::Object& object : forwardScene.objects) object.material.shader = "varc/Forward";
    for (scene::Light& l : forwardScene.lights) l.renderMode = scene::LightRenderMode::Important;
    auto forwardRenderer = ForwardRenderer::create(context(), {&*mPack});
    ASSERT_TRUE(forwardRenderer) << forwardRenderer.error().detail;
    auto forward = forwardRenderer->render(forwardScene);
    ASSERT_TRUE(forward) << forward.error().detail;
    RenderedFrame deferred = render(*deferredScene);
    auto expected = reference::renderDeferredReference(*deferredScene);
    ASSERT_TRUE(expected) << expected.error().detail;
    reference::Tolerance tolerance;
    tolerance.interiorLsb = tolerance.edgeLsb = 2.0f;
    reference::CompareResult result =
        reference::compareImages(deferred.image, forward->image, expected->classes, tolerance);
    uint64_t intervals = 0;
    if (expected->colorHigh.width()) {
        for (uint32_t y = 0; y < expected->color.height(); ++y)
            for (uint32_t x = 0; x < expected->color.width(); ++x)
                intervals += expected->color.pixelFloat(x, y) != expected->colorHigh.pixelFloat(x, y);
    }
    EXPECT_LE(result.failingPixels, intervals) << result.message;
    EXPECT_GT(result.maxErrorLsb, 0.0f) << "two different paths cannot agree bit for bit";
    bool shadowDrawn = false;
    for (const std::string& variant : forward->variants)
        shadowDrawn = shadowDrawn || variant.find("SHADOWS_DEPTH") != std::string::npos;
    EXPECT_TRUE(shadowDrawn) << "the forward render must draw the shadowed add-pass variant";
}

}  // namespace
}  // namespace varc::render
