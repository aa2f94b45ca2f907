// SPDX-License-Identifier: Apache-2.0
// Value tests of the include files added for TextCore text, the Standard shader's simple forward
// path, UnityDeprecated.cginc and the GLSL includes (issue #27, docs/BUILTIN_API.md): each group
// runs on lavapipe over a grid of inputs (tests/vulkan/helpers/{TextCore,StandardSimple,
// GlslInclude}Values.shader, pixel centre (u, v) as input) and is compared with the formula
// stated in the include file, computed here.
//
// clang-format off
// api-value-tested: BRDF3DirectSimple TransformToTangentSpace TangentSpaceLightingInput
// api-value-tested: MetallicSetup_Reflectivity SpecularSetup_Reflectivity RoughnessSetup_Reflectivity
// api-value-tested: SmithGGXVisibilityTerm CookTorranceVisibilityTerm KelemenVisibilityTerm
// api-value-tested: ModifiedKelemenVisibilityTerm SebLagardeFresnelTerm LazarovFresnelTerm
// api-value-tested: RDFBlinnPhongNormalizedTerm RoughnessToSpecPower DotClamped LambertTerm BlinnTerm
// api-value-tested: saturate GetStereoMatrixVP WorldSpaceViewDir ObjSpaceViewDir
// api-value-tested: WorldSpaceLightDir ObjSpaceLightDir
// clang-format on
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <glm/glm.hpp>
#include <string>

#include "FormulaComparison.h"
#include "QuadDrawTest.h"
#include "varc/reader/Pack.h"
#include "varc/reader/PassView.h"
#include "varc/reader/ShaderView.h"
#include "varc/render/BuiltinTextures.h"
#include "varc/render/SceneValues.h"

namespace varc::render {
namespace {

constexpr uint32_t kSize = 32;
constexpr double kPi = 3.14159265358979;
using Vec3 = std::array<double, 3>;
using Vec4 = std::array<double, 4>;
using Formula = std::function<Vec4(double u, double v)>;

double linearFromSrgb(double x) {  // IEC 61966-2-1
    return x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4);
}
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 normalize(const Vec3& a) {
    double n = std::sqrt(dot(a, a));
    return {a[0] / n, a[1] / n, a[2] / n};
}
Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double pow5(double x) { return x * x * x * x * x; }
// Blinn-Phong exponent of perceptual roughness r: 2 / alpha^2 - 2 with alpha = r^2.
double specPower(double r) { return 2.0 / std::max(std::pow(r, 4.0), 1e-4) - 2.0; }

class TextCoreSimpleValueTest : public testing::QuadDrawTest {
protected:
    TextCoreSimpleValueTest() : QuadDrawTest(kSize) {}

    // Draws |keyword| of |shader| and compares the first |channels| channels of every pixel with
    // |formula| within |absolute| + |relative| * |expected|; reports the worst pixel.
    void expectFormula(const std::string& shader, const std::string& keyword,
                       const Formula& formula, int channels, double absolute, double relative,
                       const ShaderValues& values = {}) {
        auto view = mPack->findShader(shader);
        ASSERT_TRUE(view) << shader;
        const BuiltinTextures& builtin = *mTextures;
        TextureLookup textures = [&builtin](std::string_view, pack::ResourceDim dim) {
            return builtin.named("white", dim);
        };
        image::Image image = drawQuad(*view->pass(0), {keyword}, values, textures);
        ASSERT_EQ(image.width(), kSize) << keyword;
        testing::FormulaComparison result =
            testing::compareWithFormula(image, formula, channels, absolute, relative);
        EXPECT_LE(result.worst, 1.0) << keyword << ": worst " << result.where;
        EXPECT_GT(result.largest, 0.05) << keyword << ": the expected values are all near zero";
    }
};

// TextCore's SRGBToLinear(float4): the sRGB curve on rgb, alpha unchanged.
TEST_F(TextCoreSimpleValueTest, TextCoreSrgbToLinear) {
    expectFormula(
        "Test/TextCoreValues", "API_SRGB4",
        [](double u, double v) {
            return Vec4{linearFromSrgb(u), linearFromSrgb(v), linearFromSrgb(u * v), 0.25 + v};
        },
        4, 1e-4, 1e-3);
}

// diffColor + specColor (n + 2) / 2 max(rl, 0)^n, n = the exponent of 1 - smoothness.
TEST_F(TextCoreSimpleValueTest, Brdf3DirectSimple) {
    expectFormula(
        "Test/StandardSimpleValues", "API_BRDF3",
        [](double u, double v) {
            double n = std::clamp(specPower(1 - (0.1 + 0.5 * u)), 1e-4, 10000.0);
            double spec = (n + 2) / 2 * std::pow(v, n);
            return Vec4{u + spec * (0.04 + 0.5 * v), v + spec * 0.3, 0.2 + spec * u, 0};
        },
        3, 1e-4, 2e-3);
}

// The light and eye vectors in the frame (t, cross(n, t) w, n); the eye vector normalised.
TEST_F(TextCoreSimpleValueTest, TangentSpaceLightingInput) {
    expectFormula(
        "Test/StandardSimpleValues", "API_TANGENT_SPACE",
        [](double u, double v) {
            Vec3 n = normalize({u - 0.5, 1.0, v - 0.5});
            Vec3 t = normalize({1.0, 0.2 * u, 0.3 * v});
            Vec3 b = cross(n, t);
            double w = v > 0.5 ? -1.0 : 1.0;
            b = {b[0] * w, b[1] * w, b[2] * w};
            Vec3 l{0.3, u, v}, e{v, -0.5, 0.2};
            Vec3 et = normalize({dot(t, e), dot(b, e), dot(n, e)});
            return Vec4{dot(t, l), dot(b, l), dot(n, l), et[1]};
        },
        4, 1e-4, 1e-3);
}

// Metallic: 1 - 0.96 (1 - metallic); specular: the largest component of _SpecColor; the default
// workflow (SpecularSetup) for UNIFORM_REFLECTIVITY; each scaled by u or v so that the stage
// reads its input.
TEST_F(TextCoreSimpleValueTest, UniformReflectivity) {
    ShaderValues values;
    values.set("_Metallic", 0.3f);
    values.set("_SpecColor", glm::vec4(0.2f, 0.6f, 0.4f, 1.0f));
    expectFormula(
        "Test/StandardSimpleValues", "API_REFLECTIVITY",
        [](double u, double v) {
            double metallic = 1 - 0.96 * (1 - 0.3);
            return Vec4{metallic * u, 0.6 * v, metallic * v, 0.6 * u};
        },
        4, 1e-4, 1e-3, values);
}

// The 5.x visibility terms, G / (NdotL NdotV): Smith-Schlick (k = alpha / 2), Cook-Torrance,
// Kelemen 1 / LdotH^2 and Kelemen with Schlick's k = alpha sqrt(2 / pi).
TEST_F(TextCoreSimpleValueTest, DeprecatedVisibilityTerms) {
    expectFormula(
        "Test/StandardSimpleValues", "API_VISIBILITY",
        [](double u, double v) {
            double r = 0.3 + 0.5 * u, k = r * r / 2;
            double smith = 1 / ((u * (1 - k) + k) * (v * (1 - k) + k) + 1e-5);
            double nl = 0.2 + 0.8 * u, nv = 0.2 + 0.8 * v, nh = 0.5 + 0.5 * v, vh = 0.3 + 0.7 * u;
            double g = std::min({1.0, 2 * nh * nv / vh, 2 * nh * nl / vh});
            double lh = 0.3 + 0.7 * u, lh2 = 0.3 + 0.7 * v, k2 = u * u * std::sqrt(2 / kPi);
            double gh = lh2 * (1 - k2) + k2;
            return Vec4{smith, g / (nl * nv + 1e-4), 1 / (lh * lh + 1e-5), 1 / (gh * gh + 1e-5)};
        },
        4, 1e-4, 2e-3);
}

// Lagarde: F0 + (max(1 - r, F0) - F0) (1 - cos)^5; Lazarov: F0 + (1 - F0) (1 - cos)^5 / (1 + 3 r).
TEST_F(TextCoreSimpleValueTest, DeprecatedFresnelTerms) {
    expectFormula(
        "Test/StandardSimpleValues", "API_FRESNEL",
        [](double u, double v) {
            Vec3 f0{0.04, 0.5 * v, u};
            double t = pow5(1 - v), tl = pow5(1 - u) / (1 + 3 * v);
            auto lagarde = [&](double f) { return f + (std::max(1 - u, f) - f) * t; };
            auto lazarov = [&](double f) { return f + (1 - f) * tl; };
            return Vec4{lagarde(f0[1]), lagarde(f0[2]), lazarov(f0[0]), lazarov(f0[2])};
        },
        4, 1e-4, 1e-3);
}

// (n + 2) / (2 pi) NdotH^n, the exponent of perceptual roughness, and max(0, dot(a, b)).
TEST_F(TextCoreSimpleValueTest, DeprecatedSpecularHelpers) {
    expectFormula(
        "Test/StandardSimpleValues", "API_SPEC_POWER",
        [](double u, double v) {
            double n = 1 + 20 * v;
            Vec3 a{u - 0.5, v, 0.2}, b = normalize({0.3, -0.4, 1.0});
            double d = std::max(0.0, dot(a, b));
            return Vec4{(n + 2) / (2 * kPi) * std::pow(u, n),
                        std::max(specPower(0.2 + 0.8 * u), 1e-4), 2 * d, d};
        },
        4, 1e-4, 2e-3);
}

// GLSL: saturate, ParallaxOffset, GetStereoMatrixVP without stereo (unity_MatrixVP) and Luminance.
TEST_F(TextCoreSimpleValueTest, GlslHelpers) {
    ShaderValues values;
    glm::mat4 vp(1.0f);
    vp[0] = glm::vec4(2, 0, 0, 0);
    vp[1] = glm::vec4(0.5f, 1, 0, 0);
    vp[2] = glm::vec4(3, 0, 1, 0);
    vp[3] = glm::vec4(-1, 0, 0, 1);
    values.set("unity_MatrixVP", vp);
    expectFormula(
        "Test/GlslIncludeValues", "API_GLSL_MISC",
        [](double u, double v) {
            Vec3 view = normalize({u - 0.5, v - 0.5, 0.3 + u});
            double height = 0.2 + 0.5 * v, centred = u * height - height / 2;
            return Vec4{std::clamp(3 * u - 1, 0.0, 1.0), centred * view[0] / (view[2] + 0.42),
                        2 * u + 0.5 * v + 1.5 - 1, 0.2126729 * u + 0.7151522 * v + 0.072175 * 0.5};
        },
        4, 1e-4, 1e-3, values);
}

// View and light directions of object point p = (u, v, 0.5, 1), for an object scaled by 2 and
// moved to (1, 2, 3), the camera at (4, 5, 6) and a point light at (0.5, -1, 2): UnityCG.glslinc's
// and UnityCG.cginc's (the value-tested names cover both files).
ShaderValues directionValues() {
    ShaderValues values;
    glm::mat4 objectToWorld(2.0f);
    objectToWorld[3] = glm::vec4(1, 2, 3, 1);
    values.set("unity_ObjectToWorld", objectToWorld);
    values.set("unity_WorldToObject", glm::inverse(objectToWorld));
    values.set("_WorldSpaceCameraPos", glm::vec3(4, 5, 6), 0.0f);
    values.set("_WorldSpaceLightPos0", glm::vec4(0.5f, -1, 2, 1));
    return values;
}
Vec4 directions(double u, double v) {
    return Vec4{4 - (2 * u + 1), (5 - 2) / 2.0 - v, 0.5 - (2 * u + 1), (0.5 - 1) / 2.0 - u};
}

TEST_F(TextCoreSimpleValueTest, ViewAndLightDirections) {
    expectFormula("Test/GlslIncludeValues", "API_GLSL_DIRECTIONS", directions, 4, 1e-4, 1e-3,
                  directionValues());
    expectFormula("Test/StandardSimpleValues", "API_CG_DIRECTIONS", directions, 4, 1e-4, 1e-3,
                  directionValues());
}

}  // namespace
}  // namespace varc::render
