// SPDX-License-Identifier: Apache-2.0
// compareImages, with the mutation tests of docs/LIGHTING.md §9.2: the comparator must fail a
// reference rendered with a wrong attenuation, a missing add pass or a swapped light type, and pass
// the identical image and one with ±1 LSB noise.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "varc/reference/ImageCompare.h"
#include "varc/reference/ReferenceRenderer.h"
#include "varc/scene/LightTextures.h"

namespace varc::reference {
namespace {

// Seed 000's technique: a sphere and a plane lit by a directional light (base pass), a point and
// a spot light (two add passes), with ambient.
scene::Scene mutationScene() {
    scene::Scene s;
    s.camera.width = s.camera.height = 96;
    s.camera.position = {0, 1.5f, -3.5f};
    s.ambient = glm::vec3(0.08f);
    scene::Object ball;
    ball.material.shader = "Custom/My First Lighting Shader";
    ball.material.properties["_Tint"] = glm::vec4(0.9f, 0.6f, 0.4f, 1.0f);
    ball.material.properties["_Smoothness"] = 0.5f;
    scene::Object floor = ball;
    floor.mesh = scene::MeshKind::Plane;
    floor.transform.position = {0, -0.5f, 0};
    floor.transform.scale = glm::vec3(0.3f);
    s.objects = {floor, ball};
    scene::Light sun;
    sun.intensity = 0.4f;
    sun.transform.rotationDegrees = {50, -30, 0};
    scene::Light point;
    point.type = scene::LightType::Point;
    point.transform.position = {0.8f, 0.3f, -0.6f};
    point.range = 3.0f;
    point.color = {1.0f, 0.5f, 0.2f};
    scene::Light spot;
    spot.type = scene::LightType::Spot;
    spot.transform.position = {-0.5f, 2.0f, -0.5f};
    spot.transform.rotationDegrees = {80, 0, 0};
    spot.range = 5.0f;
    spot.spotAngle = 50.0f;
    spot.intensity = 1.5f;
    s.lights = {sun, point, spot};
    return s;
}

ReferenceImage render(const scene::Scene& s, const ReferenceOptions& options = {}) {
    auto image = renderReference(s, options);
    EXPECT_TRUE(image.ok()) << (image.ok() ? "" : image.error().detail);
    return std::move(image).value();
}

class ImageCompareTest : public ::testing::Test {
protected:
    void SetUp() override {
        mScene = mutationScene();
        mReference = render(mScene);
        const auto a = scene::assignForwardLights(mScene, mScene.objects[1]);
        ASSERT_EQ(a.mainDirectional, 0);
        ASSERT_EQ(a.addLights.size(), 2u);
    }
    CompareResult compareWith(const image::Image& rendered) {
        return compareImages(rendered, mReference.color, mReference.classes);
    }

    scene::Scene mScene;
    ReferenceImage mReference;
};

TEST_F(ImageCompareTest, IdenticalImagePasses) {
    const CompareResult r = compareWith(mReference.color);
    EXPECT_TRUE(r.passed) << r.message;
    EXPECT_EQ(r.maxErrorLsb, 0.0f);
    EXPECT_EQ(r.failingPixels, 0u);
    EXPECT_GT(r.interiorPixels, 2000u);
    EXPECT_GT(r.edgePixels, 100u);
    EXPECT_EQ(r.diff.width(), 96u);
    // The 8-bit readback of the same pixels passes too (LDR references are multiples of 1/255).
    EXPECT_TRUE(compareWith(mReference.color.toRgba8()).passed);
}

TEST_F(ImageCompareTest, OneLsbNoisePasses) {
    image::Image noisy = mReference.color.toRgba8();
    std::mt19937 random(5);
    std::uniform_int_distribution<int> lsb(-1, 1);
    for (uint8_t& byte : noisy.bytes()) byte = static_cast<uint8_t>(std::clamp(byte + lsb(random), 0, 255));
    const CompareResult r = compareWith(noisy);
    EXPECT_TRUE(r.passed) << r.message;
    EXPECT_NEAR(r.maxErrorLsb, 1.0f, 1e-3f);
    EXPECT_LT(std::abs(r.meanSignedErrorLsb), 0.05f);
}

TEST_F(ImageCompareTest, SystematicOneLsbBiasFailsOnTheMean) {
    image::Image biased = mReference.color.toRgba8();
    for (uint8_t& byte : biased.bytes()) byte = static_cast<uint8_t>(std::min(255, byte + 1));
    const CompareResult r = compareWith(biased);
    EXPECT_FALSE(r.passed) << r.message;
    EXPECT_EQ(r.failingPixels, 0u);  // every pixel is within 1 LSB ...
    EXPECT_GT(r.meanSignedErrorLsb, 0.25f);  // ... but the mean is not
}

TEST_F(ImageCompareTest, SingleWrongInteriorPixelIsReported) {
    image::Image wrong = mReference.color.toRgba8();
    uint32_t x = 0, y = 0;
    for (uint32_t i = 0; i < 96 * 96; ++i) {
        if (mReference.classes.classes[i] == PixelClass::Interior) {
            x = i % 96;
            y = i / 96;
            break;
        }
    }
    auto p = wrong.pixel8(x, y);
    p[1] = static_cast<uint8_t>(p[1] >= 128 ? p[1] - 2 : p[1] + 2);
    wrong.setPixel8(x, y, p);
    const CompareResult r = compareWith(wrong);
    EXPECT_FALSE(r.passed);
    EXPECT_EQ(r.failingPixels, 1u);
    ASSERT_EQ(r.firstFailures.size(), 1u);
    EXPECT_EQ(r.firstFailures[0].x, x);
    EXPECT_EQ(r.firstFailures[0].y, y);
    EXPECT_NEAR(r.firstFailures[0].errorLsb, 2.0f, 1e-3f);
    EXPECT_EQ(r.diff.pixel8(x, y)[1], 255);  // failing pixels are flagged in green
    Tolerance loose;
    loose.interiorLsb = 2.0f;
    EXPECT_TRUE(compareImages(wrong, mReference.color, mReference.classes, loose).passed);
}

// The mask shows what each pixel was checked as: its class, an interval, or a mismatch.
TEST_F(ImageCompareTest, MaskColoursPixelClassesIntervalsAndMismatches) {
    image::Image wrong = mReference.color.toRgba8();
    image::Image high = mReference.color;
    uint32_t edge = 0, background = 0;
    std::vector<uint32_t> interior;
    for (uint32_t i = 0; i < 96 * 96; ++i) {
        const PixelClass cls = mReference.classes.classes[i];
        if (cls == PixelClass::Interior) interior.push_back(i);
        if (cls == PixelClass::Edge) edge = i;
        if (cls == PixelClass::Background) background = i;
    }
    ASSERT_GE(interior.size(), 2u);
    const uint32_t failing = interior[0], interval = interior[1];
    auto p = wrong.pixel8(failing % 96, failing / 96);
    p[1] = static_cast<uint8_t>(p[1] >= 128 ? p[1] - 9 : p[1] + 9);
    wrong.setPixel8(failing % 96, failing / 96, p);
    auto h = high.pixelFloat(interval % 96, interval / 96);
    h[0] = h[0] > 0.5f ? h[0] - 0.1f : h[0] + 0.1f;  // the reference is now an interval here
    high.setPixelFloat(interval % 96, interval / 96, h);
    const CompareResult r =
        compareImages(wrong, mReference.color, mReference.classes, Tolerance{}, &high);
    ASSERT_EQ(r.mask.width(), 96u);
    EXPECT_EQ(r.mask.pixel8(failing % 96, failing / 96), kMaskMismatch);
    EXPECT_EQ(r.mask.pixel8(interval % 96, interval / 96), kMaskInterval);
    EXPECT_EQ(r.mask.pixel8(interior.back() % 96, interior.back() / 96), kMaskInterior);
    EXPECT_EQ(r.mask.pixel8(edge % 96, edge / 96), kMaskEdge);
    EXPECT_EQ(r.mask.pixel8(background % 96, background / 96), kMaskBackground);
}

// An edge pixel that shows its neighbour's colour (a one-pixel coverage difference) passes.
TEST_F(ImageCompareTest, EdgePixelMayMatchANeighbour) {
    image::Image shifted = mReference.color.toRgba8();
    int changed = 0;
    for (uint32_t y = 1; y + 1 < 96; ++y) {
        for (uint32_t x = 1; x + 1 < 96; ++x) {
            if (mReference.classes.at(x, y) != PixelClass::Edge) continue;
            shifted.setPixel8(x, y, mReference.color.toRgba8().pixel8(x + 1, y));
            ++changed;
            if (changed == 20) break;
        }
        if (changed == 20) break;
    }
    const CompareResult r = compareWith(shifted);
    EXPECT_TRUE(r.passed) << r.message;
}

TEST_F(ImageCompareTest, WrongAttenuationFails) {
    ReferenceOptions wrong;
    // d/r instead of d²/r² as the falloff coordinate.
    wrong.falloffOverride = [](float t) { return scene::falloff(std::sqrt(t)); };
    const CompareResult r = compareWith(render(mScene, wrong).color);
    EXPECT_FALSE(r.passed) << r.message;
    EXPECT_GT(r.failingPixels, 100u);
}

TEST_F(ImageCompareTest, MissingAddPassFails) {
    ReferenceOptions wrong;
    wrong.editAssignment = [](scene::ForwardLightAssignment& a) { a.addLights.pop_back(); };
    const CompareResult r = compareWith(render(mScene, wrong).color);
    EXPECT_FALSE(r.passed) << r.message;
    EXPECT_GT(r.failingPixels, 100u);
}

TEST_F(ImageCompareTest, SwappedLightTypeFails) {
    for (auto [index, type] : {std::pair{1, scene::LightType::Spot}, std::pair{2, scene::LightType::Point}}) {
        scene::Scene swapped = mScene;
        swapped.lights[static_cast<size_t>(index)].type = type;
        const CompareResult r = compareWith(render(swapped).color);
        EXPECT_FALSE(r.passed) << "light " << index << ": " << r.message;
    }
}

TEST_F(ImageCompareTest, SizeMismatchFails) {
    const image::Image small(32, 32, image::PixelFormat::Rgba8);
    const CompareResult r = compareWith(small);
    EXPECT_FALSE(r.passed);
    EXPECT_NE(r.message.find("sizes differ"), std::string::npos);
}

}  // namespace
}  // namespace varc::reference
