// SPDX-License-Identifier: Apache-2.0
// Value tests of the small Standard-shader terms (issue #27, docs/BUILTIN_API.md): each group of
// tests/vulkan/helpers/StandardTermsValues.shader runs on lavapipe over a 32 x 32 grid of inputs
// (pixel centre (u, v)) and is compared with the formula computed here from its documented
// meaning: GGX / Trowbridge-Reitz D = a^2 / (pi (NdotH^2 (a^2 - 1) + 1)^2), the height-correlated
// Smith visibility in its linear approximation, Burley's diffuse, Schlick's Fresnel, the
// whiteout normal blend, the box-projected probe lookup and the G-buffer layout of
// UnityGBuffer.cginc. scripts/builtin-api.py counts the functions named on the api-value-tested
// lines below as implemented.
//
// api-value-tested: SmoothnessToPerceptualRoughness PerceptualRoughnessToRoughness GGXTerm
// api-value-tested: SmoothnessToRoughness SmithJointGGXVisibilityTerm DisneyDiffuse
// api-value-tested: FresnelTerm FresnelLerp Unity_SafeNormalize BlendNormals UnpackScaleNormal
// api-value-tested: UnpackScaleNormalRGorAG EnergyConservationBetweenDiffuseAndSpecular
// api-value-tested: SpecularStrength LerpWhiteTo LerpOneTo OneMinusReflectivityFromMetallic
// api-value-tested: ParallaxOffset1Step BoxProjectedCubemapDirection PreMultiplyAlpha
// api-value-tested: perceptualRoughnessToMipmapLevel mipmapLevelToPerceptualRoughness
// api-value-tested: UnityGlossyEnvironmentSetup UnityStandardDataToGbuffer
// api-value-tested: UnityStandardDataFromGbuffer UnityLambertLight UnityBlinnPhongLight
// api-value-tested: ResetUnityGI ResetUnityLight ImportanceSampleLambert
// api-value-tested: UNITY_GLOSSY_ENV_FROM_SURFACE
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <glm/glm.hpp>
#include <string>

#include "FormulaComparison.h"
#include "QuadDrawTest.h"

namespace varc::render {
namespace {

constexpr uint32_t kSize = 32;
constexpr double kPi = 3.14159265358979323846;
using Vec3 = std::array<double, 3>;
using Vec4 = std::array<double, 4>;
using Formula = std::function<Vec4(double u, double v)>;

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 normalized(Vec3 a) {
    double len = std::sqrt(dot(a, a));
    return {a[0] / len, a[1] / len, a[2] / len};
}
Vec3 testNormal(double u, double v) { return normalized({u - 0.5, v - 0.5, 0.6 + 0.3 * u}); }
double pow5(double x) { return x * x * x * x * x; }

// Trowbridge-Reitz / GGX normal distribution for roughness alpha (1e-7 keeps alpha -> 0 finite).
double ggx(double nDotH, double alpha) {
    double a2 = alpha * alpha, d = nDotH * nDotH * (a2 - 1.0) + 1.0;
    return a2 / (kPi * (d * d + 1e-7));
}
// Height-correlated Smith visibility G / (4 NdotL NdotV), linear approximation of each lambda
// (sqrt(x^2 (1 - a^2) + a^2) ~ x (1 - a) + a); 1e-5 keeps the grazing limit finite.
double smithJoint(double nDotL, double nDotV, double alpha) {
    double lambdaV = nDotL * (nDotV * (1 - alpha) + alpha);
    double lambdaL = nDotV * (nDotL * (1 - alpha) + alpha);
    return 0.5 / (lambdaV + lambdaL + 1e-5);
}
// Burley's diffuse retro-reflection factor (the 1/pi is left to the caller).
double disney(double nDotV, double nDotL, double lDotH, double perceptualRoughness) {
    double fd90 = 0.5 + 2 * lDotH * lDotH * perceptualRoughness;
    return (1 + (fd90 - 1) * pow5(1 - nDotL)) * (1 + (fd90 - 1) * pow5(1 - nDotV));
}
// Schlick: F0 + (F90 - F0) (1 - cos)^5.
double schlick(double f0, double f90, double cosA) { return f0 + (f90 - f0) * pow5(1 - cosA); }

// Single-step parallax: the height h * height - height / 2 along the normalised tangent-space
// view direction whose z is biased by 0.42.
std::array<double, 2> parallax(double h, double height, Vec3 view) {
    view = normalized(view);
    double shift = h * height - height / 2, z = view[2] + 0.42;
    return {shift * view[0] / z, shift * view[1] / z};
}

// The reflected ray from |pos| leaves the probe box [lo, hi] at pos + dir t; the lookup
// direction is that exit point seen from the probe centre.
Vec3 boxProjected(const Vec3& refl, const Vec3& pos, const Vec3& centre, const Vec3& lo,
                  const Vec3& hi) {
    Vec3 dir = normalized(refl);
    double t = 1e30;
    for (int k = 0; k < 3; ++k) t = std::min(t, ((dir[k] > 0 ? hi[k] : lo[k]) - pos[k]) / dir[k]);
    Vec3 out;
    for (int k = 0; k < 3; ++k) out[k] = pos[k] - centre[k] + dir[k] * t;
    return out;
}

class StandardTermsValueTest : public testing::QuadDrawTest {
protected:
    StandardTermsValueTest() : QuadDrawTest(kSize) {}

    void expectFormula(const std::string& keyword, const ShaderValues& values,
                       const Formula& formula, int channels, double absolute, double relative) {
        expectPassFormula("Test/StandardTermsValues", keyword, values, whiteTextures(), formula, channels,
                          absolute, relative);
    }
};

// Smoothness s -> perceptual roughness 1 - s -> roughness (1 - s)^2, and the GGX distribution.
TEST_F(StandardTermsValueTest, RoughnessAndGgx) {
    expectFormula(
        "ST_ROUGH", {},
        [](double u, double v) {
            return Vec4{1 - u, v * v, (1 - u) * (1 - u), ggx(u, 0.05 + 0.9 * v)};
        },
        4, 1e-5, 1e-3);
}

// Visibility over the grid and at the grazing limit (NdotL = NdotV = 0), Burley's diffuse, and
// the GGX peak 1 / (pi a^2) at NdotH = 1.
TEST_F(StandardTermsValueTest, VisibilityDiffuseAndPeak) {
    expectFormula(
        "ST_MICRO", {},
        [](double u, double v) {
            double alpha = 0.2 + 0.5 * u;
            return Vec4{smithJoint(u, v, 0.1 + 0.8 * u * v), disney(v, u, 0.5 * (u + v), 1 - u * v),
                        smithJoint(0, 0, v), 1.0 / (kPi * alpha * alpha)};
        },
        4, 1e-5, 1e-3);
}

TEST_F(StandardTermsValueTest, Fresnel) {
    expectFormula(
        "ST_FRESNEL", {},
        [](double u, double v) {
            return Vec4{schlick(v, 1, u), schlick(0.5, 1, u), schlick(u, 1, v), schlick(0.2, v, v)};
        },
        4, 1e-5, 1e-4);
}

// v / sqrt(max(0.001, v.v)): unit length above |v| = sqrt(0.001), scaled down below it.
TEST_F(StandardTermsValueTest, SafeNormalize) {
    expectFormula(
        "ST_SAFENORM", {},
        [](double u, double v) {
            Vec3 a = {0.2 * (u - 0.5), 0.2 * (v - 0.5), 0};
            double len = std::sqrt(std::max(0.001, dot(a, a)));
            return Vec4{a[0] / len, a[1] / len, 0, 1};
        },
        4, 1e-5, 1e-4);
}

// Whiteout blend: normalize(n1.xy + n2.xy, n1.z n2.z).
TEST_F(StandardTermsValueTest, BlendNormals) {
    expectFormula(
        "ST_BLEND", {},
        [](double u, double v) {
            Vec3 a = testNormal(u, v), b = testNormal(v, 1 - u);
            Vec3 n = normalized({a[0] + b[0], a[1] + b[1], a[2] * b[2]});
            return Vec4{n[0], n[1], n[2], 0};
        },
        3, 1e-5, 1e-4);
}

// Normal maps are plain RGB in varc (UNITY_NO_DXT5nm): n = rgb * 2 - 1 with xy scaled by the
// bump scale, z as stored; the RG-or-AG form is the same there.
TEST_F(StandardTermsValueTest, UnpackScaleNormal) {
    expectFormula(
        "ST_UNPACK", {},
        [](double u, double v) {
            return Vec4{(2 * u - 1) * (0.5 + v), u, (2 * v - 1) * 2 * u, u};
        },
        4, 1e-5, 1e-4);
}

// Specular workflow: 1 - reflectivity = 1 - max(specular.rgb), diffuse = albedo * that; and the
// metallic workflow's (1 - 0.04) (1 - metallic) in linear colour space.
TEST_F(StandardTermsValueTest, EnergyConservation) {
    expectFormula(
        "ST_ENERGY", {},
        [](double u, double v) {
            double oneMinusReflectivity = 1 - std::max({0.1, 0.5 * v, 0.3 * u});
            return Vec4{u * oneMinusReflectivity, v * oneMinusReflectivity, oneMinusReflectivity,
                        std::max({u, v, 0.5})};
        },
        4, 1e-5, 1e-4);
    expectFormula(
        "ST_LERP", {},
        [](double u, double v) {
            return Vec4{1 - v + u * v, 1 - v + 0.3 * v, 1 - v + u * v, 0.96 * (1 - u)};
        },
        4, 1e-5, 1e-4);
}

// PreMultiplyAlpha changes colour and alpha only in the Transparent mode (_ALPHAPREMULTIPLY_ON):
// diffuse * alpha, and alpha raised by the reflectivity 1 - oneMinusReflectivity.
TEST_F(StandardTermsValueTest, PreMultiplyAlphaOnlyInTheTransparentMode) {
    expectFormula(
        "ST_PREMUL", {}, [](double u, double v) { return Vec4{u, v, v, 0}; }, 4, 1e-5, 1e-4);
    expectFormula(
        "ST_PREMUL_ON", {},
        [](double u, double v) {
            double oneMinusReflectivity = 0.3 + 0.5 * u;
            return Vec4{u * v, v * v, 1 - oneMinusReflectivity + v * oneMinusReflectivity, 0};
        },
        4, 1e-5, 1e-4);
}

TEST_F(StandardTermsValueTest, ParallaxOffset) {
    expectFormula(
        "ST_PARALLAX", {},
        [](double u, double v) {
            auto a = parallax(u, 0.5, {u - 0.5, v - 0.5, 0.3 + v});
            auto b = parallax(1 - v, 0.1 + 0.2 * u, {0.7, -0.2, 0.01 * v});
            return Vec4{a[0], a[1], b[0], b[1]};
        },
        4, 2e-6, 1e-3);
}

// Left half: a box probe (centre.w = 1); right half: an infinite probe (w = 0), direction kept.
TEST_F(StandardTermsValueTest, BoxProjection) {
    expectFormula(
        "ST_BOX", {},
        [](double u, double v) {
            Vec3 refl = {u - 0.5, v - 0.5, 0.4 - v}, pos = {0.2 * u, 0.1, -0.3 * v};
            if (u >= 0.5) return Vec4{refl[0], refl[1], refl[2], 0};
            Vec3 d = boxProjected(refl, pos, {0.1, 0.2, 0.3}, {-2, -1, -1.5}, {1.5, 2, 1});
            return Vec4{d[0], d[1], d[2], 0};
        },
        3, 1e-5, 1e-4);
}

// Perceptual roughness r <-> mip r * UNITY_SPECCUBE_LOD_STEPS (6); the glossy-environment setup
// takes roughness 1 - smoothness and the reflection of the view ray, reflect(-V, N).
TEST_F(StandardTermsValueTest, ProbeMipAndSetup) {
    expectFormula(
        "ST_MIP", {},
        [](double u, double v) {
            Vec3 view = testNormal(u, v), n = normalized({0.2, u - 0.5, 1.0});
            double refl = -view[0] + 2 * dot(n, view) * n[0];
            return Vec4{6 * u, v, 1 - v, refl};
        },
        4, 1e-5, 1e-4);
}

// The G-buffer layout: RT0 = (diffuse, occlusion), RT1 = (specular, smoothness), RT2 =
// (normal * 0.5 + 0.5, 1); unpacking returns the values and the unit normal.
TEST_F(StandardTermsValueTest, GbufferPacking) {
    expectFormula(
        "ST_GBUF_TO", {},
        [](double u, double v) {
            Vec3 n = testNormal(u, v);
            return Vec4{1 - u, v + 0.3 + 0.5 * v, n[0] * 0.5 + 0.5, n[1] * 0.5 + 0.5 + 1};
        },
        4, 1e-5, 1e-4);
    expectFormula(
        "ST_GBUF_FROM", {},
        [](double u, double v) {
            Vec3 n = normalized({2 * u - 1, 2 * v - 1, 0.8});
            return Vec4{n[0], n[2], 0.25 + 0.5 * v + u, 0.7 + v};
        },
        4, 1e-5, 1e-4);
}

// The legacy light models with _SpecColor (0.3, 0.6, 0.9): Lambert albedo * light * max(0, N.L),
// alpha s.Alpha; Blinn-Phong adds light * _SpecColor * max(0, N.H)^(Specular * 128) * Gloss with
// H the normalised light + view direction.
TEST_F(StandardTermsValueTest, LegacyLightModels) {
    ShaderValues values;
    values.set("_SpecColor", glm::vec4(0.3f, 0.6f, 0.9f, 1.0f));
    expectFormula(
        "ST_LEGACY", values,
        [](double u, double v) {
            Vec3 n = testNormal(u, v), l = normalized({0.3, -0.4, 0.8});
            Vec3 view = normalized({u - 0.3, 0.2, 1.0});
            Vec3 h = normalized({l[0] + view[0], l[1] + view[1], l[2] + view[2]});
            double diff = std::max(0.0, dot(n, l));
            double spec =
                std::pow(std::max(0.0, dot(n, h)), (0.05 + 0.4 * v) * 128) * (0.25 + 0.5 * u);
            return Vec4{u * 1.0 * diff, v * 0.5 * diff + 0.5 * 0.6 * spec,
                        0.5 * 2.0 * diff + 2.0 * 0.9 * spec, 1.5};
        },
        4, 1e-5, 1e-3);
}

// The resets: no light (black, N.L 0, a non-null direction (0, 1, 0)) and no indirect light,
// whatever the struct held.
TEST_F(StandardTermsValueTest, GiResets) {
    expectFormula(
        "ST_RESET", {},
        [](double, double) {
            return Vec4{0, 1, 1, 1};
        },
        4, 1e-6, 0);
}

// Cosine-weighted sample about N = z: sin(theta) = sqrt(u.x), phi = 2 pi u.y; its weight over
// the pdf is 1 (both are N.L / pi).
TEST_F(StandardTermsValueTest, LambertSample) {
    expectFormula(
        "ST_LAMBERT", {},
        [](double u, double v) {
            double r = std::sqrt(u), phi = 2 * kPi * v;
            return Vec4{r * std::cos(phi), r * std::sin(phi), std::sqrt(1 - u), 1.0};
        },
        4, 1e-5, 1e-4);
}

// The glossy-environment data of a standard surface: roughness 1 - Smoothness, direction the
// view ray reflected about the surface normal.
TEST_F(StandardTermsValueTest, GlossyEnvironmentFromSurface) {
    expectFormula(
        "ST_ENVSURF", {},
        [](double u, double v) {
            Vec3 view = testNormal(u, v), n = normalized({0.2, u - 0.5, 1.0});
            double k = 2 * dot(n, view);
            return Vec4{1 - v, -view[0] + k * n[0], -view[1] + k * n[1], -view[2] + k * n[2]};
        },
        4, 1e-5, 1e-4);
}

}  // namespace
}  // namespace varc::render
