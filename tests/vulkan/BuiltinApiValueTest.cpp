// SPDX-License-Identifier: Apache-2.0
// Value tests of varc's built-in include API (issue #27, docs/BUILTIN_API.md): each group of
// functions runs on lavapipe over a grid of inputs (tests/vulkan/helpers/BuiltinApiValues.shader,
// pixel centre (u, v) as input) and is compared with the documented formula computed here.
// scripts/builtin-api.py counts a non-trivial function as implemented only when it is named on
// an api-value-tested line of a test; the names below are the ones these tests evaluate.
//
// api-value-tested: IsGammaSpace LinearToGammaSpace GammaToLinearSpace LinearToGammaSpaceExact
// api-value-tested: GammaToLinearSpaceExact ParallaxOffset UnpackHeightmap PackHeightmap
// api-value-tested: UnpackNormalWithScale UnpackNormal EncodeFloatRGBA DecodeFloatRGBA
// api-value-tested: EncodeFloatRG DecodeFloatRG LinearToSRGB SRGBToLinear Gamma22ToLinear
// api-value-tested: LinearToGamma22 LinearToST2084 ST2084ToLinear UnityMixRealtimeAndBakedShadows
// api-value-tested: TriangleWave SmoothCurve SmoothTriangleWave TRANSFORM_TEX EncodeViewNormalStereo
// api-value-tested: DecodeViewNormalStereo Stripe Linear01Depth LinearEyeDepth Squash UnityFlipSprite
// api-value-tested: CustomRenderTextureRotate2D ScreenDitherToAlpha PaintContextUVToBrushUV
// api-value-tested: PaintContextPixelsToBrushUV UnityCalcTriEdgeTessFactors UnityDistanceFromPlane
// api-value-tested: UnityCalcEdgeTessFactor UnityEncodeRGBM DecodeLightmapRGBM MultiplyUV DecodeHDR
// api-value-tested: UnpackNormalmapRGorAG DecodeLightmapDoubleLDR UIGammaToLinear UnityGet2DClipping
// api-value-tested: UnityGetUIDiffuseColor UnpackScaleNormalDXT5nm CreateTangentToWorldPerVertex
// api-value-tested: CalculateSurfaceGradient PerturbNormal UnitySampleShadowmap_PCF3x3
// api-value-tested: UnitySampleShadowmap_PCF5x5Tent UnitySampleShadowmap_PCF7x7 UnityCombineShadowcoordComponents
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "FormulaComparison.h"
#include "QuadDrawTest.h"
#include "varc/reader/Pack.h"
#include "varc/reader/PassView.h"
#include "varc/reader/ShaderView.h"
#include "varc/render/BuiltinTextures.h"
#include "varc/render/DrawResources.h"
#include "varc/render/RenderStateResolver.h"
#include "varc/render/SceneValues.h"
#include "varc/render/VariantPipeline.h"
#include "varc/render/VertexLayout.h"
#include "varc/vulkan/Buffer.h"
#include "varc/vulkan/RenderTarget.h"

namespace varc::render {
namespace {

constexpr uint32_t kSize = 32;
using Vec4 = std::array<double, 4>;
using Formula = std::function<Vec4(double u, double v)>;

// The documented formulas.
double srgbFromLinear(double x) {  // IEC 61966-2-1
    if (x <= 0.0) return 0.0;
    return x <= 0.0031308 ? 12.92 * x : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}
double linearFromSrgb(double x) {
    return x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4);
}
constexpr double kM1 = 2610.0 / 16384.0, kM2 = 2523.0 / 4096.0 * 128.0, kC1 = 3424.0 / 4096.0,
                 kC2 = 2413.0 / 4096.0 * 32.0, kC3 = 2392.0 / 4096.0 * 32.0;
double pqFromLinear(double l) {  // SMPTE ST 2084, 1 = 10000 cd/m^2
    double y = std::pow(l, kM1);
    return std::pow((kC1 + kC2 * y) / (1.0 + kC3 * y), kM2);
}
double linearFromPq(double e) {
    double p = std::pow(e, 1.0 / kM2);
    return std::pow(std::max(p - kC1, 0.0) / (kC2 - kC3 * p), 1.0 / kM1);
}
double frac(double x) { return x - std::floor(x); }
double triangleWave(double x) { return std::abs(frac(x + 0.5) * 2.0 - 1.0); }
double smoothCurve(double x) { return x * x * (3.0 - 2.0 * x); }
// Unity's parallax offset: the height centred on 0, along the view's xy over its z + 0.42.
std::array<double, 2> parallax(double h, double height, std::array<double, 3> view) {
    double n = std::sqrt(view[0] * view[0] + view[1] * view[1] + view[2] * view[2]);
    double centred = h * height - height / 2.0;
    double z = view[2] / n + 0.42;
    return {centred * view[0] / n / z, centred * view[1] / n / z};
}

class BuiltinApiValueTest : public testing::QuadDrawTest {
protected:
    BuiltinApiValueTest() : QuadDrawTest(kSize) {}

    // Draws the variant of |keyword| and returns the float image.
    image::Image run(const std::string& keyword, const ShaderValues& values) {
        reader::PassView pass = *mPack->findShader("Test/BuiltinApiValues")->pass(0);
        const BuiltinTextures& builtin = *mTextures;
        TextureLookup textures = [&builtin](std::string_view, pack::ResourceDim dim) {
            return builtin.named("white", dim);
        };
        return drawQuad(pass, {keyword}, values, textures);
    }

    // Runs |keyword| and compares the first |channels| channels of every pixel with |formula|
    // within |absolute| + |relative| * |expected|; reports the worst pixel.
    void expectFormula(const std::string& keyword, const Formula& formula, int channels,
                       double absolute, double relative, const ShaderValues& values = {}) {
        image::Image image = run(keyword, values);
        ASSERT_EQ(image.width(), kSize) << keyword;
        testing::FormulaComparison result =
            testing::compareWithFormula(image, formula, channels, absolute, relative);
        EXPECT_LE(result.worst, 1.0) << keyword << ": worst " << result.where;
        EXPECT_GT(result.largest, 0.05) << keyword << ": the expected values are all near zero";
    }

};

// varc renders in linear space: IsGammaSpace() is false; LinearToGammaSpace is the sRGB curve.
TEST_F(BuiltinApiValueTest, GammaSpaceAndSrgbCurves) {
    expectFormula("API_GAMMA", [](double u, double v) {
        return Vec4{srgbFromLinear(u), srgbFromLinear(v), srgbFromLinear(u * v), 0.0};
    }, 4, 1e-4, 1e-3);
    expectFormula("API_GAMMA_EXACT", [](double u, double v) {
        return Vec4{linearFromSrgb(u), linearFromSrgb(v), linearFromSrgb(u * v),
                    srgbFromLinear(u) + linearFromSrgb(v)};
    }, 4, 1e-4, 1e-3);
}

TEST_F(BuiltinApiValueTest, ParallaxOffset) {
    expectFormula("API_PARALLAX", [](double u, double v) {
        std::array<double, 3> view{u - 0.5, v - 0.5, 0.3 + u};
        auto a = parallax(u, 0.2 + 0.5 * v, view);
        auto b = parallax(v, 0.4, {view[1], view[0], view[2]});
        return Vec4{a[0], a[1], b[0], b[1]};
    }, 4, 1e-5, 1e-3);
}

// Heights in two 8-bit channels (Vulkan does not guarantee R16 sampling): r low byte, g high byte
// of the 16-bit height, h = (r + 256 g) / 257 with r, g in [0, 1].
TEST_F(BuiltinApiValueTest, Heightmaps) {
    expectFormula("API_HEIGHTMAP", [](double u, double v) {
        double value = std::round(v * 65535.0), high = std::floor(value / 256.0);
        return Vec4{(u + v * 256.0) / 257.0, std::round(u * 65535.0) / 65535.0,
                    (value - high * 256.0) / 255.0, high / 255.0};
    }, 4, 2e-5, 1e-4);
}

// Plain RGB normal maps (UNITY_NO_DXT5nm): n = rgb * 2 - 1, xy scaled, not renormalised.
TEST_F(BuiltinApiValueTest, NormalUnpacking) {
    expectFormula("API_NORMAL_SCALE", [](double u, double v) {
        double scale = 0.25 + 2.0 * u * v;
        return Vec4{(u * 2 - 1) * scale, (v * 2 - 1) * scale, (0.5 + 0.5 * u * v) * 2 - 1, 0};
    }, 3, 1e-5, 1e-4);
    expectFormula("API_NORMAL", [](double u, double v) {
        return Vec4{u * 2 - 1, v * 2 - 1, (1 - u * v) * 2 - 1, 0};
    }, 3, 1e-5, 1e-4);
}

// EncodeFloatRGBA/RG split a value in [0, 1) into base-255 digits; decoding gives it back.
TEST_F(BuiltinApiValueTest, FloatEncodings) {
    expectFormula("API_ENCODE_FLOAT", [](double u, double v) {
        double x = v * 0.973;  // frac(255 x) stays 0.015 away from a jump at every pixel
        double r = frac(x * 1.0), g = frac(x * 255.0);
        return Vec4{u * 0.999, u * 0.999, r - g / 255.0, g};
    }, 4, 2e-4, 1e-4);
}

TEST_F(BuiltinApiValueTest, ColorGamutTransferFunctions) {
    expectFormula("API_SRGB", [](double u, double v) {
        return Vec4{srgbFromLinear(u), srgbFromLinear(v), srgbFromLinear(u * v * 0.01),
                    linearFromSrgb(v)};
    }, 4, 1e-4, 1e-3);
    expectFormula("API_GAMMA22", [](double u, double v) {
        return Vec4{std::pow(u, 2.2), std::pow(v, 2.2), std::pow(u, 1 / 2.2), std::pow(v, 1 / 2.2)};
    }, 4, 1e-4, 1e-3);
    expectFormula("API_PQ", [](double u, double v) {
        return Vec4{pqFromLinear(u), pqFromLinear(v * 0.01), pqFromLinear(u * v), linearFromPq(v)};
    }, 4, 1e-4, 2e-3);
}

// The Rec. 709 -> Rec. 2020 matrix of ITU-R BT.2087 and the Rec. 709 -> P3-D65 matrix, and
// their inverses (a round trip gives the colour back).
TEST_F(BuiltinApiValueTest, ColorGamutPrimaries) {
    expectFormula("API_PRIMARIES", [](double u, double v) {
        double r = u, g = v, b = 1 - u;
        return Vec4{0.627404 * r + 0.329283 * g + 0.043313 * b,
                    0.017083 * r + 0.072397 * g + 0.910520 * b, g, b};
    }, 4, 2e-4, 1e-3);
}

// With a realtime shadow and a shadow mask: min(saturate(realtime + fade), baked).
TEST_F(BuiltinApiValueTest, MixRealtimeAndBakedShadows) {
    expectFormula("API_SHADOW_MIX", [](double u, double v) {
        return Vec4{std::min(std::min(u + 0.5 * u * v, 1.0), v), 0, 0, 0};
    }, 1, 1e-5, 1e-4);
}

// The wind animation's periodic helpers (GPU Gems 3, chapter 16).
TEST_F(BuiltinApiValueTest, TerrainEngineWaves) {
    expectFormula("API_TERRAIN_WAVES", [](double u, double v) {
        double z = 4 * u - 1.3, w = 3 * v + 0.2;
        return Vec4{triangleWave(u), smoothCurve(v * 0.5 + 0.25), smoothCurve(triangleWave(z)),
                    smoothCurve(triangleWave(w))};
    }, 4, 1e-4, 1e-3);
}

// TRANSFORM_TEX(uv, name) = uv * name_ST.xy + name_ST.zw; EncodeViewNormalStereo is the
// stereographic projection n.xy / (n.z + 1) scaled by 1 / 1.7777 into [0, 1], and
// DecodeViewNormalStereo inverts it.
std::array<double, 3> viewNormal(double u, double v) {
    double x = u - 0.5, y = v - 0.5, z = 0.6, n = std::sqrt(x * x + y * y + z * z);
    return {x / n, y / n, z / n};
}
TEST_F(BuiltinApiValueTest, TransformTexAndViewNormalEncoding) {
    expectFormula("API_TRANSFORM_TEX", [](double u, double v) {
        auto n = viewNormal(u, v);
        return Vec4{u * 2.0 + 0.25, v * -3.0 + 0.5, n[0] / (n[2] + 1.0) / 1.7777 * 0.5 + 0.5,
                    n[1] / (n[2] + 1.0) / 1.7777 * 0.5 + 0.5};
    }, 4, 1e-5, 1e-4);
    expectFormula("API_VIEW_NORMAL", [](double u, double v) {
        auto n = viewNormal(u, v);
        return Vec4{n[0], n[1], n[2], 0};
    }, 3, 1e-4, 1e-4);
}

// Terrain-tool previews: an anti-aliased stripe, 1 on the line, 0 at pixelWidth from it.
TEST_F(BuiltinApiValueTest, TerrainPreviewStripe) {
    expectFormula("API_STRIPE", [](double u, double v) {
        return Vec4{std::clamp(1.0 - std::abs(u - 0.5) / 0.2, 0.0, 1.0),
                    std::clamp(1.0 - std::abs(v - 0.3) / 0.05, 0.0, 1.0), 0, 0};
    }, 2, 1e-5, 1e-4);
}

// Depth: with _ZBufferParams as SHADER_ABI.md §4.2 gives it, Linear01Depth(z) = 1 / (x z + y)
// (eye depth / far) and LinearEyeDepth(z) = 1 / (z' z + w) (eye depth).
TEST_F(BuiltinApiValueTest, LinearDepth) {
    const double near = 0.3, far = 100.0;
    const double x = 1.0 - far / near, y = far / near, z = x / far, w = 1.0 / near;
    ShaderValues values;
    values.set("_ZBufferParams", glm::vec4(float(x), float(y), float(z), float(w)));
    expectFormula("API_DEPTH", [&](double u, double v) {
        return Vec4{1.0 / (x * u + y), 1.0 / (z * v + w), 0, 0};
    }, 2, 1e-5, 1e-4, values);
}

// Squash moves a vertex towards the plane (n, d) by 1 - amount; UnityFlipSprite multiplies xy by
// the flip.
TEST_F(BuiltinApiValueTest, SquashAndSpriteFlip) {
    const double n[3] = {0.0, 0.6, 0.8}, d = -0.2, amount = 0.25;
    ShaderValues values;
    values.set("_SquashPlaneNormal", glm::vec4(float(n[0]), float(n[1]), float(n[2]), float(d)));
    values.set("_SquashAmount", float(amount));
    expectFormula("API_SQUASH_FLIP", [&](double u, double v) {
        double p[3] = {u, v, u * v};
        double distance = p[0] * n[0] + p[1] * n[1] + p[2] * n[2] + d;
        Vec4 out{};
        for (int c = 0; c < 3; ++c) {
            double onPlane = p[c] - distance * n[c];
            out[static_cast<size_t>(c)] = onPlane + (p[c] - onPlane) * amount;
        }
        out[3] = -u;
        return out;
    }, 4, 1e-5, 1e-4, values);
}

// A 2D rotation by angle (counter-clockwise); the LOD dither keeps coverage c0 of each 4 x 4
// tile: the pixel whose ordered-dither threshold ((rank + 0.5) / 16, Bayer order) is below c0.
TEST_F(BuiltinApiValueTest, RotationAndDither) {
    static const int kRank[16] = {0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5};
    expectFormula("API_ROTATE_DITHER", [](double u, double v) {
        double angle = v * 3.0;
        int px = static_cast<int>(std::floor(u * 32.0)), py = static_cast<int>(std::floor(v * 32.0));
        double threshold = (kRank[(py % 4) * 4 + px % 4] + 0.5) / 16.0;
        return Vec4{u * std::cos(angle) - v * std::sin(angle), u * std::sin(angle) + v * std::cos(angle),
                    u > threshold ? 1.0 : 0.0, 0};
    }, 3, 1e-5, 1e-4);
}

// Terrain-tool paint contexts: affine maps set by the tool.
TEST_F(BuiltinApiValueTest, PaintContextMaps) {
    ShaderValues values;
    values.set("_PCUVToBrushUVScales", glm::vec4(2.0f, 0.5f, -0.25f, 1.5f));
    values.set("_PCUVToBrushUVOffset", glm::vec4(0.1f, -0.2f, 0.0f, 0.0f));
    values.set("_BrushUV_PCPixelsX", glm::vec4(0.03f, 0.01f, 0.0f, 0.0f));
    values.set("_BrushUV_PCPixelsY", glm::vec4(-0.02f, 0.04f, 0.0f, 0.0f));
    values.set("_BrushUV_Offset", glm::vec4(0.5f, 0.25f, 0.0f, 0.0f));
    expectFormula("API_PAINT", [](double u, double v) {
        double px = u * 32.0, py = v * 32.0;
        return Vec4{u * 2.0 + v * -0.25 + 0.1, u * 0.5 + v * 1.5 - 0.2,
                    px * 0.03 + py * -0.02 + 0.5, px * 0.01 + py * 0.04 + 0.25};
    }, 4, 1e-5, 1e-4, values);
}

// Tessellation factors: edges the mean of their two vertices' factors, inside the mean of
// three; the signed distance to a plane; an edge's factor = its length * screen height /
// (edgeLen * its middle's distance to the camera), at least 1.
TEST_F(BuiltinApiValueTest, TessellationFactors) {
    ShaderValues values;
    values.set("_WorldSpaceCameraPos", glm::vec3(0.5f, 0.25f, -1.0f), 0.0f);
    values.set("_ScreenParams", glm::vec4(640.0f, 480.0f, 1.0f + 1.0f / 640.0f, 1.0f + 1.0f / 480.0f));
    expectFormula("API_TESSELLATION", [](double u, double v) {
        double f0 = u * 8.0, f1 = v * 8.0, f2 = u * v * 8.0;
        double mid[3] = {u + 0.25 - 0.5, v * 0.5 - 0.25, 2.0 + 1.0};
        double dist = std::sqrt(mid[0] * mid[0] + mid[1] * mid[1] + mid[2] * mid[2]);
        double len = std::sqrt(0.25 + v * v);
        return Vec4{0.5 * (f1 + f2), (f0 + f1 + f2) / 3.0, 0.6 * u + 0.8 * v - 0.5,
                    std::max(len * 480.0 / (4.0 * dist), 1.0)};
    }, 4, 1e-5, 1e-4, values);
}

// RGBM: rgb / max divided by the largest channel rounded up to 1/255, which is stored in alpha;
// decoding multiplies back (x = max, y = 1).
TEST_F(BuiltinApiValueTest, RgbmEncoding) {
    expectFormula("API_RGBM", [](double u, double v) {
        double c[3] = {u * 4.0, v * 2.0, u * v};
        double alpha = std::max(std::max(c[0] / 5.0, c[1] / 5.0), std::max(c[2] / 5.0, 1e-6));
        alpha = std::ceil(alpha * 255.0) / 255.0;
        return Vec4{c[0], c[1], c[2], alpha};
    }, 4, 1e-4, 1e-3);
}

// MultiplyUV = (M (u, v, 0, 0)).xy; DecodeHDR = x * a^y * rgb in linear space and x * a * rgb in
// gamma space (a = w (alpha - 1) + 1); RG/AG normals: x = r * a, y = g, z = sqrt(1 - x^2 - y^2)
// after the * 2 - 1; double-LDR lightmaps: x * rgb.
TEST_F(BuiltinApiValueTest, DecodingHelpers) {
    expectFormula("API_DECODE_MISC", [](double u, double v) {
        double gammaR = 3.0 * v * u;
        double linearG = 3.0 * std::pow(v, 2.2) * v;
        double nx = u * 2 - 1, ny = v * 2 - 1;
        double nz = std::sqrt(1 - std::clamp(nx * nx + ny * ny, 0.0, 1.0));
        return Vec4{2 * u + 0.5 * v, -1 * u + 3 * v, gammaR + linearG, nz + 2 * v};
    }, 4, 1e-4, 1e-3);
}

// UI: the sRGB decoding of gamma-space colours, the RectMask2D test (1 inside the rectangle,
// edges included) and the two-texture diffuse colour (white textures: 1 + the sample add).
TEST_F(BuiltinApiValueTest, UiHelpers) {
    expectFormula("API_UI", [](double u, double v) {
        bool inside = u >= 0.25 && u <= 0.75 && v >= 0.3 && v <= 0.6;
        return Vec4{linearFromSrgb(u), linearFromSrgb(v), inside ? 1.0 : 0.0, 1.0 + u};
    }, 4, 1e-4, 1e-3);
}

// DXT5nm normals (x in alpha, y in green) scaled in xy; the tangent frame's binormal
// cross(n, t) * sign * unity_WorldTransformParams.w (-1 here: a mirroring object); the surface-
// gradient bump n - (dhdx r1 + dhdy r2) / dot(dpdx, r1), normalised (r1 = dpdy x n, r2 = n x dpdx).
TEST_F(BuiltinApiValueTest, NormalFrames) {
    ShaderValues values;
    values.set("unity_WorldTransformParams", glm::vec4(0.0f, 0.0f, 0.0f, -1.0f));
    expectFormula("API_NORMAL_FRAME", [](double u, double v) {
        double x = (u * 2 - 1) * 0.8, y = (v * 2 - 1) * 0.8;
        double z = std::sqrt(1 - std::clamp(x * x + y * y, 0.0, 1.0));
        double dhdx = u - 0.5, dhdy = v * 0.3;
        return Vec4{x, z, v, -dhdx / std::sqrt(dhdx * dhdx + dhdy * dhdy + 1.0)};
    }, 4, 1e-4, 1e-3, values);
}

// The PCF tents over a map of depth 1 (white): their weights sum to 1, so a receiver in front of
// it (depth <= 1) is fully lit and one behind it fully shadowed; UnityCombineShadowcoordComponents
// adds the offset times the receiver plane's slope to the depth.
TEST_F(BuiltinApiValueTest, ShadowFilters) {
    ShaderValues values;
    values.set("_ShadowMapTexture_TexelSize", glm::vec4(1.0f / 64, 1.0f / 64, 64.0f, 64.0f));
    expectFormula("API_PCF", [](double u, double v) {
        double lit = 2.0 * u <= 1.0 ? 1.0 : 0.0;  // receiver depth 2u against the map's 1
        return Vec4{lit, lit, lit, v + 0.5 * 2 + 0.25 * 4};
    }, 4, 1e-4, 1e-4, values);
}

}  // namespace
}  // namespace varc::render
