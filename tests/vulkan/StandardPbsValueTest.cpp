// SPDX-License-Identifier: Apache-2.0
// Value tests of the Standard-pipeline include files (issue #27, docs/BUILTIN_API.md): each
// group runs on lavapipe over a grid of inputs (tests/vulkan/helpers/StandardPbsValues.shader,
// pixel centre (u, v) as input) and is compared with the formula stated in the include file,
// computed here.
//
// clang-format off
// api-value-tested: UnityMeta_RGBToHSV UnityMeta_RGBToHSVHelper BRDF3_Direct BRDF3_Indirect
// api-value-tested: BRDF2_Unity_PBS UnityStandardDataApplyWeightToGbuffer MetallicRough
// api-value-tested: NormalizePerPixelNormal WorldNormal Hash ImportanceSampleGGXDir
// api-value-tested: ImportanceSampleGGX ImportanceSampleCosDir
// api-value-tested: SubtractMainLightWithRealtimeAttenuationFromLightmap DecodeDirectionalSpecularLightmap
// clang-format on
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
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
using Vec3 = std::array<double, 3>;
using Vec4 = std::array<double, 4>;
using Formula = std::function<Vec4(double u, double v)>;

double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec3 normalize(const Vec3& a) {
    double n = std::sqrt(dot(a, a));
    return {a[0] / n, a[1] / n, a[2] / n};
}
double lerp(double a, double b, double t) { return a + (b - a) * t; }
double saturate(double x) { return std::clamp(x, 0.0, 1.0); }

// Hexcone HSV (as in Python's colorsys): hue sector of the largest component.
Vec3 hsv(double r, double g, double b) {
    double mx = std::max({r, g, b}), mn = std::min({r, g, b}), c = mx - mn;
    double h = 0;
    if (c > 0) {
        if (mx == r) {
            h = (g - b) / c;
        } else if (mx == g) {
            h = 2 + (b - r) / c;
        } else {
            h = 4 + (r - g) / c;
        }
        h = h / 6 - std::floor(h / 6);
    }
    return {h, mx > 0 ? c / mx : 0, mx};
}

class StandardPbsValueTest : public testing::QuadDrawTest {
protected:
    StandardPbsValueTest() : QuadDrawTest(kSize) {}

    // Draws |keyword| of Test/StandardPbsValues and compares the first |channels| channels of
    // every pixel with |formula| within |absolute| + |relative| * |expected|.
    void expectFormula(const std::string& keyword, const Formula& formula, int channels,
                       double absolute, double relative, const ShaderValues& values = {}) {
        auto view = mPack->findShader("Test/StandardPbsValues");
        ASSERT_TRUE(view);
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

// UnityMeta_RGBToHSV(u, v, 0.5) against the hexcone HSV; the helper's hue for the green sector
// (offset 2, V = 1.1): frac((2 + (u - v) / (1.1 - min(u, v))) / 6).
TEST_F(StandardPbsValueTest, RgbToHsv) {
    expectFormula(
        "API_HSV",
        [](double u, double v) {
            Vec3 c = hsv(u, v, 0.5);
            double chroma = 1.1 - std::min(u, v);
            double h = 0;
            if (chroma > 0) {
                double x = (2 + (u - v) / chroma) / 6;
                h = x - std::floor(x);
            }
            return Vec4{c[0], c[1], c[2], h};
        },
        4, 1e-4, 1e-3);
}

// BRDF3_Direct: diff + spec (n + 2) / 2 rlPow4^(n / 4), n = 2 / a^2 - 2, a = (1 - s)^2;
// BRDF3_Indirect (red): ind.diffuse * diff + ind.specular * lerp(spec, grazing, fresnel).
TEST_F(StandardPbsValueTest, Brdf3) {
    expectFormula(
        "API_BRDF3",
        [](double u, double v) {
            double s = 0.1 + 0.5 * u, a = (1 - s) * (1 - s);
            double n = std::clamp(2 / std::max(a * a, 1e-4) - 2, 1e-4, 10000.0);
            double lobe = (n + 2) / 2 * std::pow(v, n / 4);
            double indirect = 0.5 * u + v * lerp(0.04 + 0.5 * v, 0.7 * u, v);
            return Vec4{u + lobe * (0.04 + 0.5 * v), v + lobe * 0.3, 0.2 + lobe * u, indirect};
        },
        4, 1e-4, 2e-3);
}

// BRDF2_Unity_PBS with the file's formula (GGX with folded visibility/Fresnel, surface
// reduction, fourth-power Fresnel towards the grazing colour).
TEST_F(StandardPbsValueTest, Brdf2) {
    expectFormula(
        "API_BRDF2",
        [](double u, double v) {
            Vec3 l = normalize({u - 0.5, v - 0.5, 1.0});
            Vec3 view = normalize({0.3, 0.2, 1.0});
            Vec3 h = {l[0] + view[0], l[1] + view[1], l[2] + view[2]};
            double hl = std::sqrt(std::max(0.001, dot(h, h)));
            h = {h[0] / hl, h[1] / hl, h[2] / hl};
            double nl = saturate(l[2]), nh = saturate(h[2]), nv = saturate(view[2]);
            double lh = saturate(dot(l, h));
            double smoothness = 0.2 + 0.7 * u, pr = 1 - smoothness, r = pr * pr, a2 = r * r;
            double d = nh * nh * (a2 - 1) + 1.00001;
            double spec =
                std::clamp(a2 / (std::max(0.1, lh * lh) * (r + 0.5) * d * d * 4), 0.0, 100.0);
            double reduction = 1 - r * pr * (0.6 - 0.08 * pr);
            double grazing = saturate(smoothness + 0.2);
            double f = std::pow(1 - nv, 4);
            Vec3 diff{u, v, 0.2}, specColor{0.04 + 0.3 * v, 0.3, 0.2};
            Vec3 lightColor{1.0, 0.8, 0.6}, giDiffuse{0.1, 0.2, 0.3}, giSpecular{0.4, 0.5, 0.6};
            Vec4 out{0, 0, 0, 1};
            for (int c = 0; c < 3; ++c) {
                out[c] = (diff[c] + spec * specColor[c]) * lightColor[c] * nl +
                         giDiffuse[c] * diff[c] +
                         reduction * giSpecular[c] * lerp(specColor[c], grazing, f);
            }
            return out;
        },
        4, 1e-4, 2e-3);
}

// Weighted G-buffer layers: diffuse rgb, specular rgba and normal rgb scaled by the weight,
// occlusion (gbuffer0.a) kept.
TEST_F(StandardPbsValueTest, GbufferWeight) {
    expectFormula(
        "API_GBUFFER_WEIGHT",
        [](double u, double) {
            double w = 0.25 + 0.5 * u;
            return Vec4{u * w, 0.9, 0.5 * w, u * w};
        },
        4, 1e-4, 1e-3);
}

// MetallicRough without maps: (_Metallic, 1 - _Glossiness); NormalizePerPixelNormal normalises
// (the full path); WorldNormal is the normalised third row.
TEST_F(StandardPbsValueTest, MetallicRoughAndNormals) {
    ShaderValues values;
    values.set("_Metallic", 0.3f);
    values.set("_Glossiness", 0.6f);
    expectFormula(
        "API_METALLIC_ROUGH",
        [](double u, double v) {
            Vec3 n = normalize({u, v, 0.5});
            Vec3 w = normalize({u - 0.5, v, 0.3});
            return Vec4{0.3 * u, 0.4 * v, n[0], w[1]};
        },
        4, 1e-4, 1e-3, values);
}

// Thomas Wang's hash of the file, in 32-bit arithmetic, over 2^32.
double wangHash(uint32_t s) {
    s = (s ^ 61u) ^ (s >> 16);
    s *= 9u;
    s = s ^ (s >> 4);
    s *= 0x27d4eb2du;
    s = s ^ (s >> 15);
    return s * 2.3283064365386963e-10;
}
struct GgxSample {
    Vec3 h, l;
};
// GGX half vector for (u, v) around +z (alpha 0.5) and V mirrored about it.
GgxSample ggxSample(double u, double v, const Vec3& view) {
    const double a2 = 0.25;
    double cosTheta = std::sqrt((1 - u) / (1 + (a2 - 1) * u));
    double sinTheta = std::sqrt(std::max(0.0, 1 - cosTheta * cosTheta));
    double phi = 2 * 3.14159265358979 * v;
    Vec3 h = normalize({sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta});
    double vh = dot(view, h);
    return {h, {2 * vh * h[0] - view[0], 2 * vh * h[1] - view[1], 2 * vh * h[2] - view[2]}};
}

// ImportanceSampleGGXDir's L.xy and H.z for (u, v); Hash of the integer 64 (2x + 1) + (2y + 1).
TEST_F(StandardPbsValueTest, ImportanceSampleGgxDirAndHash) {
    expectFormula(
        "API_IBL_DIR",
        [](double u, double v) {
            GgxSample s = ggxSample(u, v, normalize({0.2, 0.1, 1.0}));
            auto key = static_cast<uint32_t>(std::lround(u * 64) * 64 + std::lround(v * 64));
            return Vec4{s.l[0], s.l[1], s.h[2], wangHash(key)};
        },
        4, 2e-4, 1e-3);
}

// ImportanceSampleGGX: VdotH, NdotL and weightOverPdf = 4 Vis NdotL VdotH / NdotH with the
// height-correlated visibility of alpha 0.5; ImportanceSampleCosDir's L.z = sqrt(1 - u).
TEST_F(StandardPbsValueTest, ImportanceSampleGgxWeight) {
    expectFormula(
        "API_IBL_WEIGHT",
        [](double u, double v) {
            Vec3 view = normalize({0.2, 0.1, 1.0});
            GgxSample s = ggxSample(u, v, view);
            double nh = saturate(s.h[2]), vh = saturate(dot(view, s.h)), nl = saturate(s.l[2]);
            double nv = view[2], a = 0.5;
            double vis = 0.5 / (nl * (nv * (1 - a) + a) + nv * (nl * (1 - a) + a) + 1e-5);
            double w = nh > 0 ? 4 * vis * nl * vh / nh : 0;
            return Vec4{vh, nl, w, std::sqrt(1 - u)};
        },
        4, 2e-4, 2e-3);
}

// Subtractive mode: min(lm, lerp(max(lm - NdotL (1 - atten) lightColor, shadowColor), lm,
// _LightShadowData.x)) with lm = (u, v, 0.5), atten = v, the light along +z.
TEST_F(StandardPbsValueTest, SubtractMainLightFromLightmap) {
    ShaderValues values;
    values.set("_LightColor0", glm::vec4(1.0f, 0.8f, 0.6f, 1.0f));
    values.set("_WorldSpaceLightPos0", glm::vec4(0.0f, 0.0f, 1.0f, 0.0f));
    values.set("unity_ShadowColor", glm::vec4(0.1f, 0.2f, 0.3f, 1.0f));
    values.set("_LightShadowData", glm::vec4(0.3f, 0.0f, 0.0f, 0.0f));
    expectFormula(
        "API_SUBTRACT",
        [](double u, double v) {
            Vec3 n = normalize({u - 0.5, 0.3, 1.0});
            Vec3 lm{u, v, 0.5}, light{1.0, 0.8, 0.6}, shadow{0.1, 0.2, 0.3};
            Vec4 out{0, 0, 0, 0};
            for (int c = 0; c < 3; ++c) {
                double rs = std::max(lm[c] - saturate(n[2]) * (1 - v) * light[c], shadow[c]);
                out[c] = std::min(lm[c], lerp(rs, lm[c], 0.3));
            }
            return out;
        },
        3, 1e-4, 1e-3, values);
}

// Separate directional lightmaps: dir = dirTex.xyz * 2 - 1, d = saturate(|dir|); the light gets
// color * d along dir / |dir|, the remainder color * (1 - d) is returned.
TEST_F(StandardPbsValueTest, DecodeDirectionalSpecularLightmap) {
    expectFormula(
        "API_DIRSPEC",
        [](double u, double v) {
            Vec3 dir{2 * u - 1, 2 * v - 1, 0.6};
            double len = std::sqrt(dot(dir, dir)), d = saturate(len);
            Vec3 unit{dir[0] / len, dir[1] / len, dir[2] / len};
            double ndotl = saturate(dot(normalize({0.2, 0.3, 1.0}), unit));
            return Vec4{u * (1 - d), v * d, unit[0], ndotl};
        },
        4, 1e-4, 1e-3);
}

}  // namespace
}  // namespace varc::render
