// SPDX-License-Identifier: Apache-2.0
// Value tests of built-in API functions completed by the "hlslsupport" work (issue #27,
// docs/BUILTIN_API.md): each group runs on lavapipe over a grid of inputs
// (tests/vulkan/helpers/HlslSupportValues.shader, pixel centre (u, v) as input) and is compared
// with the formula computed here from its definition (the tent weights by integrating the tent,
// the ODS offset from its geometry). scripts/builtin-api.py counts the functions named on the
// api-value-tested lines below as implemented.
//
// api-value-tested: EncodeDepthNormal DecodeDepthNormal DecodeDirectionalLightmap
// api-value-tested: DirLightmapDiffuse LightingLambert_PrePass LightingBlinnPhong_PrePass
// api-value-tested: _UnityInternalGetAreaPerTexel_3TexelsWideTriangleFilter
// api-value-tested: _UnityInternalGetWeightPerTexel_3TexelsWideTriangleFilter
// api-value-tested: _UnityInternalGetWeightPerTexel_5TexelsWideTriangleFilter
// api-value-tested: _UnityInternalGetWeightPerTexel_7TexelsWideTriangleFilter
// api-value-tested: ODSOffset UnpackNormalDXT5nm LightingLambert_Deferred
// api-value-tested: LightingBlinnPhong_Deferred UnityObjectToViewPos UnityWorldToViewPos
// api-value-tested: UnityWorldToClipPos UnityViewToClipPos UnityObjectToWorldDir
// api-value-tested: UnityWorldToObjectDir UnityObjectToWorldNormal UnityWorldSpaceViewDir
// api-value-tested: ComputeScreenPos ComputeNonStereoScreenPos ComputeGrabScreenPos
// api-value-tested: TransformViewToProjection SHEvalLinearL0L1 SHEvalLinearL2 ShadeSH12Order
// api-value-tested: ShadeSH3Order SHEvalLinearL0L1_SampleProbeVolume UnityWorldSpaceLightDir
// api-value-tested: UnityApplyLinearShadowBias UnityComputeShadowFadeDistance
// api-value-tested: UnityComputeShadowFade
// api-value-tested: _UnityInternalGetAreaAboveFirstTexelUnderAIsocelesRectangleTriangle
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
using Vec3 = std::array<double, 3>;
using Vec4 = std::array<double, 4>;
using Formula = std::function<Vec4(double u, double v)>;

double frac(double x) { return x - std::floor(x); }
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 normalized(Vec3 a) {
    double len = std::sqrt(dot(a, a));
    return {a[0] / len, a[1] / len, a[2] / len};
}
Vec3 testNormal(double u, double v) { return normalized({u - 0.5, v - 0.5, 0.6 + 0.3 * u}); }

// Unity's depth-normal encoding: the normal's stereographic projection scaled by 1 / 1.7777 into
// 0..1, then depth in two 8-bit-sized parts (x + y / 255).
Vec4 encodeDepthNormal(double depth, const Vec3& n) {
    double px = n[0] / (n[2] + 1.0) / 1.7777 * 0.5 + 0.5;
    double py = n[1] / (n[2] + 1.0) / 1.7777 * 0.5 + 0.5;
    double hi = frac(255.0 * depth);
    return {px, py, frac(depth) - hi / 255.0, hi};
}

// The share of a unit-area tent of half-width h centred at o over [a, b], by the midpoint rule.
double tentShare(double a, double b, double o, double h) {
    const int steps = 4000;
    double sum = 0, dx = (b - a) / steps;
    for (int k = 0; k < steps; ++k) {
        double x = a + (k + 0.5) * dx;
        sum += std::max(0.0, h - std::abs(x - o)) / (h * h) * dx;
    }
    return sum;
}

class HlslSupportValueTest : public testing::QuadDrawTest {
protected:
    HlslSupportValueTest() : QuadDrawTest(kSize) {}

    void expectFormula(const std::string& keyword, const ShaderValues& values,
                       const Formula& formula, int channels, double absolute, double relative) {
        expectPassFormula("Test/HlslSupportValues", keyword, values, whiteTextures(), formula, channels,
                          absolute, relative);
    }
};

TEST_F(HlslSupportValueTest, DepthNormalEncoding) {
    expectFormula(
        "HS_DEPTHNORMAL_ENC", {},
        [](double u, double v) { return encodeDepthNormal(u, testNormal(u, v)); }, 4, 2e-5, 1e-4);
    // Decoding inverts the encoding: depth and unit normal come back.
    expectFormula(
        "HS_DEPTHNORMAL_DEC", {},
        [](double u, double v) {
            Vec3 n = testNormal(u, v);
            return Vec4{v, n[0], n[1], n[2]};
        },
        4, 5e-5, 1e-4);
}

// Directional lightmaps: colour * (half-Lambert of the normal against the stored direction) /
// the stored w; Unity 4's three-basis form scales the colour by the normal's saturated
// coordinates in the basis, weighted by the scale texel, when the surface writes a normal.
TEST_F(HlslSupportValueTest, DirectionalLightmaps) {
    expectFormula(
        "HS_DIRLIGHTMAP", {},
        [](double u, double v) {
            Vec3 n = testNormal(v, u);
            double k =
                (dot(n, {u - 0.5, 0.2 - 0.5, v - 0.5}) + 0.5) / std::max(1e-4, 0.25 + 0.5 * v);
            return Vec4{u * k, v * k, 0.5 * k, 0};
        },
        3, 1e-5, 1e-4);
    expectFormula(
        "HS_RNM", {},
        [](double u, double v) {
            const double s3 = 0.57735027, a = 0.81649658, b = 0.40824830, c = 0.70710678;
            const Vec3 basis[3] = {{a, 0, s3}, {-b, c, s3}, {-b, -c, s3}};
            Vec3 n = testNormal(u, v), scale = {0.2, v, u};
            double k = 1.0;
            if (u > 0.5) {
                k = 0;
                for (int i = 0; i < 3; ++i) k += std::clamp(dot(basis[i], n), 0.0, 1.0) * scale[i];
            }
            return Vec4{u * k, v * k, 0.5 * k, v};
        },
        4, 1e-5, 1e-4);
}

// The light pre-pass: Lambert albedo * light.rgb; Blinn-Phong adds light.rgb * _SpecColor *
// (light.a * Gloss), alpha s.Alpha + spec * _SpecColor.a.
TEST_F(HlslSupportValueTest, LightPrePass) {
    ShaderValues values;
    values.set("_SpecColor", glm::vec4(0.3f, 0.6f, 0.9f, 0.5f));
    expectFormula(
        "HS_PREPASS", values,
        [](double u, double v) {
            double spec = 0.75 * u * v;
            return Vec4{u * (0.5 + u), v * v + v * 0.6 * spec, 0.5 * (1 - u) + (1 - u) * 0.9 * spec,
                        0.25 + spec * 0.5 + 0.25};
        },
        4, 1e-5, 1e-4);
}

// Deferred legacy models: G-buffer 0 = (albedo, occlusion 1), 1 = (specular colour, smoothness)
// with Lambert's black and smoothness 0 and Blinn-Phong's _SpecColor * Gloss and Specular, 2 =
// (normal * 0.5 + 0.5, 1); returned: emission + albedo * indirect diffuse (probes sampled),
// alpha 1.
TEST_F(HlslSupportValueTest, DeferredLegacyModels) {
    ShaderValues values;
    values.set("_SpecColor", glm::vec4(0.3f, 0.6f, 0.9f, 0.5f));
    expectFormula(
        "HS_DEFERRED", values,
        [](double u, double v) {
            return Vec4{0.1 + u * 0.5, 0.2 + v * u, u * v + 0.5 * v, u};
        },
        4, 1e-5, 1e-4);
    expectFormula(
        "HS_DEFERRED_GB", values,
        [](double u, double v) {
            return Vec4{0.3 * v, 0.6 * v, 0.9 * v, testNormal(u, v)[0] * 0.5 + 0.5};
        },
        4, 1e-5, 1e-4);
}

// The transforms of UnityCG.cginc with an object matrix that rotates, scales unevenly and
// translates, a view matrix and a projection: mul(M, v) is M * v of the matrices set.
struct Transforms {
    glm::dmat4 objectToWorld, worldToObject, view, projection;
    Transforms() {
        glm::dmat4 m(1.0);
        m[0] = {0.8, 0.6, 0.0, 0.0};  // columns: a rotation about z, scaled (2, 1, 0.5)
        m[1] = {-0.6, 0.8, 0.0, 0.0};
        m[0] *= 2.0;
        m[2] = {0.0, 0.0, 0.5, 0.0};
        m[3] = {0.5, -1.0, 2.0, 1.0};
        objectToWorld = m;
        worldToObject = glm::inverse(m);
        view = glm::dmat4(1.0);
        view[3] = {-0.25, 0.5, -4.0, 1.0};
        projection = glm::dmat4(0.0);
        projection[0][0] = 1.5;
        projection[1][1] = -2.0;
        projection[2][2] = 0.1;
        projection[2][3] = -1.0;
        projection[3][2] = 0.3;
    }
    void set(ShaderValues& values) const {
        values.set("unity_ObjectToWorld", glm::mat4(objectToWorld));
        values.set("unity_WorldToObject", glm::mat4(worldToObject));
        values.set("unity_MatrixV", glm::mat4(view));
        values.set("glstate_matrix_projection", glm::mat4(projection));
        values.set("unity_MatrixVP", glm::mat4(projection * view));
        values.set("_WorldSpaceCameraPos", glm::vec3(0.25f, -0.5f, 4.0f), 0.0f);
        values.set("_ProjectionParams", glm::vec4(1.0f, 0.3f, 100.0f, 0.01f));
    }
};
glm::dvec3 point(double u, double v) { return {u * 2.0 - 1.0, v, 0.5 - u}; }
Vec4 toVec4(const glm::dvec4& a) { return {a.x, a.y, a.z, a.w}; }

TEST_F(HlslSupportValueTest, Transforms) {
    Transforms t;
    ShaderValues values;
    t.set(values);
    expectFormula(
        "HS_XFORM_VIEW", values,
        [&t](double u, double v) {
            glm::dvec4 view = t.view * t.objectToWorld * glm::dvec4(point(u, v), 1.0);
            double worldViewZ = (t.view * glm::dvec4(point(u, v), 1.0)).z;
            return Vec4{view.x, view.y, view.z, worldViewZ};
        },
        4, 1e-5, 1e-5);
    expectFormula(
        "HS_XFORM_CLIP", values,
        [&t](double u, double v) {
            return toVec4(t.projection * t.view * glm::dvec4(point(u, v), 1.0));
        },
        4, 1e-5, 1e-5);
    expectFormula(
        "HS_XFORM_VIEWCLIP", values,
        [&t](double u, double v) { return toVec4(t.projection * glm::dvec4(point(u, v), 1.0)); }, 4,
        1e-5, 1e-5);
    expectFormula(
        "HS_XFORM_DIR", values,
        [&t](double u, double v) {
            glm::dvec3 world = glm::normalize(glm::dmat3(t.objectToWorld) * point(u, v));
            glm::dvec3 object = glm::normalize(glm::dmat3(t.worldToObject) * point(u, v));
            return Vec4{world.x, world.y, world.z, object.x};
        },
        4, 1e-5, 1e-5);
    // Normals with the inverse transpose; the view direction is the camera minus the point.
    expectFormula(
        "HS_XFORM_NORMAL", values,
        [&t](double u, double v) {
            glm::dvec3 n =
                glm::normalize(glm::transpose(glm::dmat3(t.worldToObject)) * point(u, v));
            return Vec4{n.x, n.y, n.z, -0.5 - point(u, v).y};
        },
        4, 1e-5, 1e-5);
}

// Screen positions: xy = (x, y * _ProjectionParams.x) / 2 + w / 2 (grab: y not flipped), zw kept;
// TransformViewToProjection applies the projection's upper 2x2 / 3x3.
TEST_F(HlslSupportValueTest, ScreenPositions) {
    Transforms t;
    ShaderValues values;
    t.set(values);
    expectFormula(
        "HS_SCREEN", values,
        [](double u, double v) {
            double x = u * 2 - 1, y = v * 2 - 1, w = 1 + u;
            return Vec4{x * 0.5 + w * 0.5, y * 0.5 * 1.0 + w * 0.5, w, y * 0.5 + w * 0.5};
        },
        4, 1e-6, 1e-5);
    expectFormula(
        "HS_VIEWPROJ", values,
        [&t](double u, double v) {
            glm::dvec3 p = point(u, v);
            glm::dvec2 p2 = glm::dmat2(t.projection) * glm::dvec2(p);
            glm::dvec3 p3 = glm::dmat3(t.projection) * p;
            return Vec4{p2.x, p2.y, p3.y, p3.z};
        },
        4, 1e-6, 1e-5);
}

// Spherical harmonics in linear space: L0 + L1 = dot(SHA, (n, 1)) per channel; L2 = dot(SHB,
// (xy, yz, zz, zx)) + SHC * (x^2 - y^2).
TEST_F(HlslSupportValueTest, SphericalHarmonics) {
    const glm::vec4 ar(0.1f, 0.2f, 0.3f, 0.5f), ag(-0.2f, 0.1f, 0.4f, 0.6f),
        ab(0.3f, -0.1f, 0.2f, 0.7f);
    const glm::vec4 br(0.05f, 0.1f, -0.2f, 0.3f), bg(0.2f, -0.3f, 0.1f, 0.05f),
        bb(-0.1f, 0.2f, 0.3f, 0.1f);
    const glm::vec4 c(0.4f, -0.3f, 0.2f, 0.0f);
    ShaderValues values;
    values.set("unity_SHAr", ar);
    values.set("unity_SHAg", ag);
    values.set("unity_SHAb", ab);
    values.set("unity_SHBr", br);
    values.set("unity_SHBg", bg);
    values.set("unity_SHBb", bb);
    values.set("unity_SHC", c);
    expectFormula(
        "HS_SH", values,
        [=](double u, double v) {
            Vec3 n = testNormal(u, v);
            glm::dvec4 n4(n[0], n[1], n[2], 1.0);
            glm::dvec4 b(n[0] * n[1], n[1] * n[2], n[2] * n[2], n[2] * n[0]);
            double vc = n[0] * n[0] - n[1] * n[1];
            auto l01 = [&](const glm::vec4& a) { return glm::dot(glm::dvec4(a), n4); };
            auto l2 = [&](const glm::vec4& bx, double cx) {
                return glm::dot(glm::dvec4(bx), b) + cx * vc;
            };
            return Vec4{l01(ar), l2(bg, c.y), l01(ab), l2(br, c.x) + l01(ag)};
        },
        4, 1e-5, 1e-4);
}

// The direction to a point light (position - p; a directional light's w = 0 keeps xyz) and the
// linear shadow bias: z + saturate(bias / w) * w, at most w.
TEST_F(HlslSupportValueTest, LightDirectionAndShadowBias) {
    ShaderValues values;
    values.set("_WorldSpaceLightPos0", glm::vec4(1.5f, 2.0f, -1.0f, 1.0f));
    values.set("unity_LightShadowBias", glm::vec4(0.6f, 0.0f, 0.0f, 0.0f));
    expectFormula(
        "HS_LIGHTDIR", values,
        [](double u, double v) {
            double w = 1.0 + u;
            double z = std::min(v * 0.5 + std::clamp(0.6 / w, 0.0, 1.0) * w, w);
            return Vec4{1.5 - (u * 2.0 - 1.0), 2.0 - v, z, 0.0};
        },
        3, 1e-5, 1e-4);
}

// Shadow fade: the distance is lerp(view depth, distance to the fade centre, centre.w); the fade
// saturate(distance * _LightShadowData.z + _LightShadowData.w).
TEST_F(HlslSupportValueTest, ShadowFade) {
    ShaderValues values;
    values.set("unity_ShadowFadeCenterAndType", glm::vec4(0.5f, -1.0f, 2.0f, 0.25f));
    values.set("_LightShadowData", glm::vec4(0.3f, 0.0f, 0.5f, -1.0f));
    expectFormula(
        "HS_FADE", values,
        [](double u, double v) {
            Vec3 p = {u * 4.0 - 2.0, v, 0.5 - u};
            Vec3 r = {p[0] - 0.5, p[1] + 1.0, p[2] - 2.0};
            double d = 3.0 * v + (std::sqrt(dot(r, r)) - 3.0 * v) * 0.25;
            auto fade = [](double x) { return std::clamp(x * 0.5 - 1.0, 0.0, 1.0); };
            return Vec4{d, fade(d), fade(4.0 * u), 0.0};
        },
        3, 1e-5, 1e-4);
}

// Tent filters: the share of the tent over each texel, integrated here.
TEST_F(HlslSupportValueTest, TentWeights) {
    expectFormula(
        "HS_TENT3", {},
        [](double u, double v) {
            double o = u - 0.5;
            return Vec4{tentShare(-2, -1, o, 1.5), 2.25 * tentShare(-1, 0, o, 1.5),
                        tentShare(0, 1, o, 1.5), tentShare(1, 2, o, 1.5) + (1.0 + 2.0 * v - 0.5)};
        },
        4, 2e-5, 1e-4);
    expectFormula(
        "HS_TENT5", {},
        [](double u, double) {
            double o = u - 0.5;
            return Vec4{tentShare(-3, -2, o, 2.5), tentShare(-1, 0, o, 2.5),
                        tentShare(0, 1, o, 2.5), tentShare(2, 3, o, 2.5)};
        },
        4, 2e-5, 1e-4);
    expectFormula(
        "HS_TENT7", {},
        [](double, double v) {
            double o = v - 0.5;
            return Vec4{tentShare(-4, -3, o, 3.5), tentShare(-1, 0, o, 3.5),
                        tentShare(1, 2, o, 3.5), tentShare(3, 4, o, 3.5)};
        },
        4, 2e-5, 1e-4);
}

// ODS: a horizontal offset of length |ipd| perpendicular to the direction from the camera.
TEST_F(HlslSupportValueTest, OdsOffset) {
    ShaderValues values;
    values.set("_WorldSpaceCameraPos", glm::vec3(0.25f, -1.0f, 0.5f), 0.0f);
    expectFormula(
        "HS_ODS", values,
        [](double u, double v) {
            Vec3 dir = {u * 4.0 - 2.0 - 0.25, v + 1.0, v * 3.0 - 1.0 - 0.5};
            double ipd = 0.5 * (u - 0.5);
            double len = std::sqrt(dir[2] * dir[2] + dir[0] * dir[0]);
            return Vec4{-dir[2] / len * ipd, 0.0, dir[0] / len * ipd, 0.0};
        },
        3, 1e-6, 1e-4);
}

// DXT5nm normal maps keep x in alpha and y in green: xy = (a, g) * 2 - 1, z from unit length.
TEST_F(HlslSupportValueTest, UnpackDxt5nm) {
    expectFormula(
        "HS_DXT5NM", {},
        [](double u, double v) {
            double x = u * 2 - 1, y = v * 2 - 1;
            return Vec4{x, y, std::sqrt(1 - std::clamp(x * x + y * y, 0.0, 1.0)), 0};
        },
        3, 1e-3, 1e-4);  // z = sqrt(1 - r^2) is steep near r = 1
}

}  // namespace
}  // namespace varc::render
