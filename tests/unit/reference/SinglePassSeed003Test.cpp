// SPDX-License-Identifier: Apache-2.0
// The single-pass reference's seed003 model (docs/LIGHTING.md §8.6): seed 003's normal is the
// model matrix's 3x3 part, unnormalised per vertex, so a uniformly scaled object's vertex lights
// scale with it; unscaled, the model renders what varc-single-pass-lit renders.
#include <algorithm>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "varc/reference/SinglePassReference.h"

namespace varc::reference {
namespace {

scene::Light directional(float yawDegrees, float intensity) {
    scene::Light l;
    l.transform.rotationDegrees = glm::vec3(0.0f, yawDegrees, 0.0f);
    l.intensity = intensity;
    return l;
}

// A sphere of the given uniform scale at the origin, seen from -z; its nearest point is a mesh
// vertex on the axis and projects onto the centre of pixel (64, 64), where n = -z. Four bright
// lights from behind (no light at that point) take the per-pixel slots; the dim fifth light,
// shining along +z onto the front, is the per-vertex light.
scene::Scene scaledSphere(const std::string& model, float scale) {
    scene::Scene s;
    s.camera.width = s.camera.height = 129;
    s.camera.path = scene::RenderPath::SinglePass;
    scene::Object sphere;
    sphere.material.shader = model == "seed003" ? "My Pipeline/Lit" : "varc/SinglePassLit";
    sphere.material.reference = model;
    sphere.transform.scale = glm::vec3(scale);
    s.objects.push_back(sphere);
    for (int i = 0; i < 4; ++i) s.lights.push_back(directional(180.0f, 1.0f));
    s.lights.push_back(directional(0.0f, 0.5f));
    return s;
}

float centre(const ReferenceImage& image) { return image.color.pixelFloat(64, 64)[0] * 255.0f; }

float maxDifferenceLsb(const ReferenceImage& a, const ReferenceImage& b) {
    float worst = 0.0f;
    for (uint32_t y = 0; y < a.color.height(); ++y) {
        for (uint32_t x = 0; x < a.color.width(); ++x) {
            for (size_t c = 0; c < 3; ++c) {
                worst = std::max(worst, std::fabs(a.color.pixelFloat(x, y)[c] -
                                                  b.color.pixelFloat(x, y)[c]));
            }
        }
    }
    return worst * 255.0f;
}

TEST(SinglePassSeed003, ScaledObjectsVertexLightsScaleWithTheNormal) {
    auto seed = renderSinglePassReference(scaledSphere("seed003", 0.5f));
    auto library = renderSinglePassReference(scaledSphere("varc-single-pass-lit", 0.5f));
    ASSERT_TRUE(seed) << seed.error().detail;
    ASSERT_TRUE(library) << library.error().detail;
    // Library: the unit normal faces the vertex light, 0.5 * 255. Seed: |n_v| = 0.5, half that.
    EXPECT_NEAR(centre(*library), 127.5f, 1.0f);
    EXPECT_NEAR(centre(*seed), 63.75f, 1.0f);
}

TEST(SinglePassSeed003, UnscaledObjectsMatchTheLibraryModel) {
    auto seed = renderSinglePassReference(scaledSphere("seed003", 1.0f));
    auto library = renderSinglePassReference(scaledSphere("varc-single-pass-lit", 1.0f));
    ASSERT_TRUE(seed) << seed.error().detail;
    ASSERT_TRUE(library) << library.error().detail;
    EXPECT_NEAR(centre(*seed), 127.5f, 1.0f);
    EXPECT_LE(maxDifferenceLsb(*seed, *library), 1.0f);
}

TEST(SinglePassSeed003, AnotherModelIsRefused) {
    scene::Scene s = scaledSphere("seed003", 1.0f);
    s.objects[0].material.reference = "seed004";
    auto image = renderSinglePassReference(s);
    ASSERT_FALSE(image);
    EXPECT_NE(image.error().detail.find("seed003"), std::string::npos) << image.error().detail;
}

}  // namespace
}  // namespace varc::reference
