// SPDX-License-Identifier: Apache-2.0
// The single-pass forward renderer on lavapipe (issue #6, seed 003's technique): the validation
// scenes against the CPU reference, and the path's rules observed in rendered pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "VulkanTestSupport.h"
#include "varc/reader/Pack.h"
#include "varc/reference/ImageCompare.h"
#include "varc/reference/SceneTolerance.h"
#include "varc/reference/SinglePassReference.h"
#include "varc/render/SinglePassRenderer.h"
#include "varc/scene/Scene.h"
#include "varc/scene/VisibleLights.h"

namespace varc::render {
namespace {

std::string scenePath(const std::string& name) {
    return VARC_TEST_SCENE_DIR "/single_pass/" + name + ".json";
}

scene::Scene loadSinglePassScene(const std::string& name) {
    auto scene = scene::loadScene(scenePath(name));
    EXPECT_TRUE(scene) << scene.error().detail;
    return scene ? std::move(*scene) : scene::Scene{};
}

// The largest per-channel RGB difference, in 8-bit LSB.
float maxDifferenceLsb(const image::Image& a, const image::Image& b) {
    return testing::maxRgbDifference(a, b) * 255.0f;
}

class SinglePassRenderTest : public testing::RendererTest<SinglePassRenderer> {
protected:
    RenderedFrame render(const scene::Scene& scene, SinglePassOptions options = {}) {
        return testing::frameOf(mRenderer->render(scene, options));
    }
};

// Every single-pass validation scene matches the CPU reference within the tolerances.
TEST_F(SinglePassRenderTest, ValidationScenesMatchTheCpuReference) {
    std::vector<std::string> scenes;
    for (const std::string& path : testing::sceneFiles("single_pass"))
        scenes.push_back(std::filesystem::path(path).stem().string());
    ASSERT_GE(scenes.size(), 5u);
    for (const std::string& name : scenes) {
        SCOPED_TRACE(name);
        scene::Scene scene = loadSinglePassScene(name);
        RenderedFrame frame = render(scene);
        auto expected = reference::renderSinglePassReference(scene);
        ASSERT_TRUE(expected) << expected.error().detail;
        reference::CompareResult result = reference::compareImages(
            frame.image, expected->color, expected->classes, reference::toleranceFor(scene));
        EXPECT_TRUE(result.passed) << result.message;
        EXPECT_GT(result.interiorPixels, 1000u) << "the scene must show its objects";
        std::printf("%-16s draws %2u  max %.2f LSB  mean %+.3f LSB\n", name.c_str(), frame.draws,
                    static_cast<double>(result.maxErrorLsb),
                    static_cast<double>(result.meanSignedErrorLsb));
    }
}

// The reference comparison notices a wrong spot rule and missing per-vertex lights.
TEST_F(SinglePassRenderTest, ComparisonCatchesAWrongSpotRuleAndMissingVertexLights) {
    scene::Scene spot = loadSinglePassScene("one-spot");
    RenderedFrame spotFrame = render(spot);
    reference::SinglePassReferenceOptions wrongSpot;
    wrongSpot.spotInnerTangentRatio = 0.5f;
    auto wrongSpotReference = reference::renderSinglePassReference(spot, wrongSpot);
    ASSERT_TRUE(wrongSpotReference) << wrongSpotReference.error().detail;
    EXPECT_FALSE(reference::compareImages(spotFrame.image, wrongSpotReference->color,
                                          wrongSpotReference->classes,
                                          reference::toleranceFor(spot))
                     .passed);

    scene::Scene eight = loadSinglePassScene("eight-lights");
    RenderedFrame eightFrame = render(eight);
    reference::SinglePassReferenceOptions pixelLightsOnly;
    pixelLightsOnly.editLights = [](scene::ObjectLightList& list) {
        list.count = std::min(list.count, 4);
    };
    auto noVertexLights = reference::renderSinglePassReference(eight, pixelLightsOnly);
    ASSERT_TRUE(noVertexLights) << noVertexLights.error().detail;
    EXPECT_FALSE(reference::compareImages(eightFrame.image, noVertexLights->color,
                                          noVertexLights->classes, reference::toleranceFor(eight))
                     .passed);
}

TEST_F(SinglePassRenderTest, LightsBeyondSixteenHaveNoEffect) {
    scene::Scene scene = loadSinglePassScene("twenty-lights");
    const scene::VisibleLightSet visible = scene::selectVisibleLights(scene);
    ASSERT_EQ(visible.slots.size() + visible.dropped.size(), 20u)
        << "every light of the scene is visible";
    ASSERT_EQ(visible.dropped.size(), 4u);

    scene::Scene kept = scene, droppedOnly = scene;
    kept.lights.clear();
    droppedOnly.lights.clear();
    for (size_t i = 0; i < scene.lights.size(); ++i) {
        bool dropped = std::find(visible.dropped.begin(), visible.dropped.end(),
                                 static_cast<int>(i)) != visible.dropped.end();
        (dropped ? droppedOnly : kept).lights.push_back(scene.lights[i]);
    }
    RenderedFrame all = render(scene), withoutDropped = render(kept),
                  onlyDropped = render(droppedOnly);
    EXPECT_EQ(maxDifferenceLsb(all.image, withoutDropped.image), 0.0f);
    // On their own the dropped lights do light the scene: dropping them is what hides them.
    scene::Scene dark = scene;
    dark.lights.clear();
    RenderedFrame darkFrame = render(dark);
    EXPECT_GT(maxDifferenceLsb(onlyDropped.image, darkFrame.image), 40.0f);
    EXPECT_GT(testing::rgbSum(onlyDropped.image), testing::rgbSum(darkFrame.image) + 20.0f);
}

TEST_F(SinglePassRenderTest, ZeroVisibleLightsGiveBlackObjects) {
    scene::Scene scene = loadSinglePassScene("zero-lights");
    ASSERT_FALSE(scene.lights.empty()) << "the scene's lights must exist but miss the frustum";
    ASSERT_TRUE(scene::selectVisibleLights(scene).slots.empty());
    ASSERT_GT(glm::length(scene.ambient), 0.0f)
        << "ambient is set, and the shader has no ambient term";
    RenderedFrame frame = render(scene);
    auto expected = reference::renderSinglePassReference(scene);
    ASSERT_TRUE(expected) << expected.error().detail;
    size_t black = 0;
    for (uint32_t y = 0; y < scene.camera.height; ++y) {
        for (uint32_t x = 0; x < scene.camera.width; ++x) {
            std::array<uint8_t, 4> p = frame.image.pixel8(x, y);
            switch (expected->classes.at(x, y)) {
                case reference::PixelClass::Interior:
                    ASSERT_EQ(p[0] + p[1] + p[2], 0)
                        << "object pixel " << x << "," << y << " is lit";
                    ++black;
                    break;
                case reference::PixelClass::Background:
                    ASSERT_NEAR(p[2], scene.camera.background.b * 255.0f, 0.5f) << x << "," << y;
                    break;
                case reference::PixelClass::Edge:
                    break;
            }
        }
    }
    EXPECT_GT(black, 1000u);
}

TEST_F(SinglePassRenderTest, InstancedAndNonInstancedRendersAgree) {
    for (const char* name : {"instanced-hdr", "sixteen-lights", "twenty-lights"}) {
        SCOPED_TRACE(name);
        scene::Scene scene = loadSinglePassScene(name);
        RenderedFrame instanced = render(scene, {.instancing = true});
        RenderedFrame separate = render(scene, {.instancing = false});
        EXPECT_EQ(separate.draws, scene.objects.size());
        EXPECT_LT(instanced.draws, separate.draws)
            << "objects sharing a material and lights are batched";
        EXPECT_TRUE(std::any_of(
            instanced.variants.begin(), instanced.variants.end(),
            [](const std::string& v) { return v.find("INSTANCING_ON") != std::string::npos; }));
        EXPECT_TRUE(std::none_of(
            separate.variants.begin(), separate.variants.end(),
            [](const std::string& v) { return v.find("INSTANCING_ON") != std::string::npos; }));
        EXPECT_EQ(maxDifferenceLsb(instanced.image, separate.image), 0.0f);
    }
}

TEST_F(SinglePassRenderTest, AllSharingObjectsFormOneInstancedDraw) {
    scene::Scene scene = loadSinglePassScene("instanced-hdr");
    RenderedFrame frame = render(scene);
    // The floor alone, and the six cubes (one material, the same two lights) in one batch.
    EXPECT_EQ(frame.draws, 2u);
}

// Instanced arrays hold 500 instances (UNITY_MAX_INSTANCE_COUNT): 501 objects that could share a
// batch take two draws.
TEST_F(SinglePassRenderTest, BatchesSplitAtTheInstancedArrayLength) {
    scene::Scene scene = loadSinglePassScene("one-directional");
    scene.camera.width = scene.camera.height = 32;
    scene::Object sphere = scene.objects[1];
    sphere.transform.scale = glm::vec3(0.05f);
    scene.objects.clear();
    for (int i = 0; i < 501; ++i) {
        sphere.transform.position = {static_cast<float>(i % 23) * 0.1f - 1.1f,
                                     static_cast<float>(i / 23) * 0.1f - 1.1f, 0};
        scene.objects.push_back(sphere);
    }
    RenderedFrame frame = render(scene);
    EXPECT_EQ(frame.draws, 2u);
}

// Only the instanced properties (_Color) may differ inside a batch: any other material property
// splits it, as does a different mesh.
TEST_F(SinglePassRenderTest, OtherPropertiesAndMeshesSplitBatches) {
    scene::Scene scene = loadSinglePassScene("instanced-hdr");
    ASSERT_EQ(render(scene).draws, 2u);
    scene.objects[1].material.properties["_Unused"] = 1.0f;
    EXPECT_EQ(render(scene).draws, 3u);
    scene.objects[2].mesh = scene::MeshKind::Sphere;
    EXPECT_EQ(render(scene).draws, 4u);
}

TEST_F(SinglePassRenderTest, UnknownShaderIsAClearError) {
    scene::Scene scene = loadSinglePassScene("one-directional");
    scene.objects[1].material.shader = "Custom/Missing";
    auto frame = mRenderer->render(scene);
    ASSERT_FALSE(frame);
    EXPECT_NE(frame.error().detail.find("Custom/Missing"), std::string::npos)
        << frame.error().detail;
}

}  // namespace
}  // namespace varc::render
