// SPDX-License-Identifier: Apache-2.0
// renderReference: whole renders whose pixel values are derived by hand from LIGHTING.md, and the
// forward light rules seen in pixels (issue #5 "Done when": out-of-range light changes nothing, two
// pixel lights add up, pixel_light_count 0 still lights through vertex lights).
#include <cmath>

#include <gtest/gtest.h>

#include "varc/reference/ReferenceRenderer.h"

namespace varc::reference {
namespace {

scene::Object sphere(const std::string& shader, glm::vec4 color = glm::vec4(1.0f)) {
    scene::Object o;
    o.material.shader = shader;
    o.material.properties["_Color"] = color;
    o.material.properties["_Tint"] = color;
    return o;
}

// 129 x 129: the sphere's nearest point (0, 0, -0.5) is a mesh vertex and projects exactly onto
// the centre of pixel (64, 64), where n = -z and v = -z.
scene::Scene centredScene(const std::string& shader) {
    scene::Scene s;
    s.camera.width = s.camera.height = 129;
    s.objects.push_back(sphere(shader));
    return s;
}

float centre(const ReferenceImage& image, int channel = 0) {
    return image.color.pixelFloat(64, 64)[static_cast<size_t>(channel)] * 255.0f;
}

scene::Light pointAt(glm::vec3 position, float range, float intensity) {
    scene::Light l;
    l.type = scene::LightType::Point;
    l.transform.position = position;
    l.range = range;
    l.intensity = intensity;
    return l;
}

// Flat ambient A with LIGHTPROBE_SH: ShadeSH9 = A for every normal, so every covered pixel of a
// white SimpleDiffuse sphere is round(255 A) and the background is the clear colour.
TEST(ReferenceRenderer, AmbientOnlyIsFlat) {
    scene::Scene s = centredScene("varc/SimpleDiffuse");
    s.ambient = {0.2f, 0.4f, 0.6f};
    auto image = renderReference(s);
    ASSERT_TRUE(image.ok()) << image.error().detail;
    size_t interior = 0;
    for (uint32_t y = 0; y < 129; ++y) {
        for (uint32_t x = 0; x < 129; ++x) {
            const auto p = image->color.pixelFloat(x, y);
            if (image->visibility.at(x, y).object == 0) {
                ++interior;
                EXPECT_EQ(p[0] * 255.0f, 51.0f);
                EXPECT_EQ(p[1] * 255.0f, 102.0f);
                EXPECT_EQ(p[2] * 255.0f, 153.0f);
            } else {
                EXPECT_EQ(p[0], 0.0f);
                EXPECT_EQ(p[3], 1.0f);
            }
        }
    }
    EXPECT_GT(interior, 400u);
    EXPECT_EQ(image->classes.at(64, 64), PixelClass::Interior);
}

// Directional light shining along +z at the camera-facing point: n = l = v, so the BRDF is
// c_d + specularTerm·F0 = 0.96 + 4 · 0.04 = 1.12 (ShadingTest derives it); E = 0.5 -> 0.56·255.
TEST(ReferenceRenderer, FacingDirectionalLightPbs) {
    for (const char* shader : {"Custom/My First Lighting Shader", "varc/Forward"}) {
        scene::Scene s = centredScene(shader);
        s.objects[0].material.properties["_Smoothness"] = 0.5f;
        scene::Light sun;
        sun.intensity = 0.5f;
        s.lights.push_back(sun);
        auto image = renderReference(s);
        ASSERT_TRUE(image.ok()) << image.error().detail;
        EXPECT_EQ(centre(*image), std::round(0.56f * 255.0f)) << shader;
        // Sun from the camera: the rim facing away is darker than the centre, not black-clamped.
        EXPECT_LT(image->color.pixelFloat(64, 54)[0], image->color.pixelFloat(64, 64)[0]);
    }
}

// Point light 1.5 m in front of the facing point, range 10: t = 2.25/100, falloff ≈ 1/(1 + 25 t)
// = 0.64 (add pass, table), and Shade4PointLights gives exactly 1/(1 + 2.25 · 25/100) = 0.64
// (vertex light with pixel_light_count 0). Both: round(0.64 · 255) = 163.
TEST(ReferenceRenderer, PointLightPixelOrVertex) {
    scene::Scene s = centredScene("varc/SimpleDiffuse");
    s.lights.push_back(pointAt({0, 0, -2}, 10.0f, 1.0f));
    auto pixel = renderReference(s);
    ASSERT_TRUE(pixel.ok());
    EXPECT_EQ(centre(*pixel), 163.0f);
    s.pixelLightCount = 0;
    auto vertex = renderReference(s);
    ASSERT_TRUE(vertex.ok());
    EXPECT_EQ(centre(*vertex), 163.0f);
}

TEST(ReferenceRenderer, OutOfRangePointLightChangesNothing) {
    scene::Scene s = centredScene("Custom/My First Lighting Shader");
    s.ambient = glm::vec3(0.1f);
    auto before = renderReference(s);
    s.lights.push_back(pointAt({0, 0, -2.5f}, 1.9f, 5.0f));  // 2.5 >= 1.9 + 0.5
    auto after = renderReference(s);
    ASSERT_TRUE(before.ok() && after.ok());
    for (uint32_t y = 0; y < 129; ++y) {
        for (uint32_t x = 0; x < 129; ++x) {
            ASSERT_EQ(before->color.pixelFloat(x, y), after->color.pixelFloat(x, y)) << x << "," << y;
        }
    }
}

// Two pixel lights of 0.32 each draw two add passes; the RGBA8 attachment rounds each:
// round(81.6) + round(81.6) = 164, where one light of 0.64 gives 163.
TEST(ReferenceRenderer, TwoPixelLightsAddUp) {
    scene::Scene s = centredScene("varc/SimpleDiffuse");
    s.lights.push_back(pointAt({0, 0, -2}, 10.0f, 0.5f));
    s.lights.push_back(pointAt({0, 0, -2}, 10.0f, 0.5f));
    auto image = renderReference(s);
    ASSERT_TRUE(image.ok());
    EXPECT_EQ(centre(*image), 164.0f);
}

TEST(ReferenceRenderer, HdrKeepsValuesAboveOne) {
    scene::Scene s = centredScene("varc/Forward");
    s.camera.hdr = true;
    scene::Light sun;
    sun.intensity = 2.0f;
    s.lights.push_back(sun);
    auto image = renderReference(s);
    ASSERT_TRUE(image.ok());
    EXPECT_NEAR(image->color.pixelFloat(64, 64)[0], 2.0f * 1.12f, 2e-3f);
}

TEST(ReferenceRenderer, TheMaterialsReferenceFieldPicksTheModel) {
    scene::Scene s = centredScene("Some/User Shader");
    EXPECT_EQ(renderReference(s).error().code, ErrorCode::NotFound);
    s.objects[0].material.reference = "varc-forward";
    EXPECT_TRUE(renderReference(s).ok());
    s.objects[0].material.reference = "no-such-model";
    auto image = renderReference(s);
    ASSERT_FALSE(image.ok());
    EXPECT_NE(image.error().detail.find("reference 'no-such-model'"), std::string::npos);
}

// A spot light straight above a receiving plane and, between them, a plane drawn with a shader
// that only casts (|shader|, alpha _Color.a against _Cutoff 0.5 where it tests alpha).
scene::Scene casterScene(const std::string& shader, float alpha,
                         const std::string& keywords = "[]") {
    const std::string json = R"({
      "camera": {"position": [0, 2, -2], "target": [0, -0.5, 0], "width": 65, "height": 65},
      "objects": [
        {"mesh": "plane", "position": [0, -0.5, 0], "scale": [0.3, 1, 0.3],
         "material": {"shader": "varc/SimpleDiffuse", "properties": {"_Color": [1, 1, 1, 1]}}},
        {"mesh": "plane", "position": [0, 0.5, 0], "scale": [0.05, 1, 0.05],
         "material": {"shader": ")" + shader + R"(", "keywords": )" + keywords + R"(,
                      "properties": {"_Color": [1, 1, 1, )" + std::to_string(alpha) + R"(],
                                     "_Cutoff": 0.5}}}],
      "lights": [{"type": "spot", "position": [0, 2, 0], "rotation": [90, 0, 0],
                  "spot_angle": 60, "range": 5, "shadows": "hard"}]})";
    auto scene = scene::parseScene(json, "caster.json");
    EXPECT_TRUE(scene.ok()) << (scene.ok() ? "" : scene.error().detail);
    return scene.ok() ? *scene : scene::Scene{};
}

float centreOf(const scene::Scene& s) {
    auto image = renderReference(s);
    EXPECT_TRUE(image.ok()) << (image.ok() ? "" : image.error().detail);
    if (!image.ok()) return -1.0f;
    for (const SurfaceSample& sample : image->visibility.samples)
        EXPECT_NE(sample.object, 1) << "a shader that only casts draws nothing in the camera";
    return image->color.pixelFloat(32, 32)[0];
}

TEST(ReferenceRenderer, CasterOnlyShadersCastAndAlphaTestAgainstCutoff) {
    const float lit = centreOf(casterScene("Legacy Shaders/Transparent/Cutout/VertexLit", 0.3f));
    const float shadowed =
        centreOf(casterScene("Legacy Shaders/Transparent/Cutout/VertexLit", 0.9f));
    EXPECT_GT(lit, shadowed + 0.1f) << "alpha 0.3 < _Cutoff: no shadow; 0.9: a shadow";
    // The opaque caster ignores alpha; so does the mutation hook for alpha-tested ones.
    EXPECT_NEAR(centreOf(casterScene("Legacy Shaders/VertexLit", 0.3f)), shadowed, 1e-6f);
    ReferenceOptions ignoring;
    ignoring.ignoreCasterCutoff = true;
    auto mutated = renderReference(
        casterScene("Legacy Shaders/Transparent/Cutout/Diffuse", 0.3f), ignoring);
    ASSERT_TRUE(mutated.ok());
    EXPECT_NEAR(mutated->color.pixelFloat(32, 32)[0], shadowed, 1e-6f);
}

TEST(ReferenceRenderer, StandardCasterFollowsTheMaterialKeywords) {
    const float shadowed = centreOf(casterScene("Standard", 0.3f));  // no keyword: opaque
    const float lit = centreOf(casterScene("Standard", 0.3f, R"(["_ALPHATEST_ON"])"));
    EXPECT_GT(lit, shadowed + 0.1f);
    // Dithered: alpha 0 is slice 0 (nothing); premultiplied alpha 0 is 0.04 (still slice 0).
    EXPECT_NEAR(centreOf(casterScene("Standard", 0.0f, R"(["_ALPHABLEND_ON"])")), lit, 1e-6f);
    EXPECT_NEAR(centreOf(casterScene("Standard", 0.0f, R"(["_ALPHAPREMULTIPLY_ON"])")), lit,
                1e-6f);
    auto both = renderReference(
        casterScene("Standard", 1.0f, R"(["_ALPHATEST_ON", "_ALPHABLEND_ON"])"));
    ASSERT_FALSE(both.ok());
    EXPECT_EQ(both.error().code, ErrorCode::InvalidInput);
}

TEST(ReferenceRenderer, RejectsWhatItCannotModel) {
    scene::Scene s = centredScene("Legacy Shaders/Reflective/Diffuse");
    auto image = renderReference(s);
    ASSERT_FALSE(image.ok());
    EXPECT_EQ(image.error().code, ErrorCode::NotFound) << "no model: rendered, not compared";
    EXPECT_EQ(image.error().detail.rfind("/objects/0: ", 0), 0u);
    s = centredScene("varc/Forward");
    s.camera.path = scene::RenderPath::Deferred;
    EXPECT_EQ(renderReference(s).error().code, ErrorCode::Unsupported);
    s = centredScene("varc/Forward");
    s.objects[0].material.properties["_MainTex"] = std::string("bricks");
    EXPECT_EQ(renderReference(s).error().code, ErrorCode::Unsupported);
    s.objects[0].material.properties["_MainTex"] = 1.0f;
    EXPECT_EQ(renderReference(s).error().code, ErrorCode::InvalidInput);
}

}  // namespace
}  // namespace varc::reference
