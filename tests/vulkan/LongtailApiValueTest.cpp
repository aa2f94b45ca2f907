// SPDX-License-Identifier: Apache-2.0
// Value tests of the virtual-texturing, UI Toolkit, indirect-draw and ray-tracing include files
// (issue #27, docs/BUILTIN_API.md): each group runs on lavapipe over a grid of inputs
// (tests/vulkan/helpers/LongtailApiValues.shader, pixel centre (u, v) as input) and is compared
// with the formula computed here.
//
// api-value-tested: GranitePrivate_RepeatUV GranitePrivate_MirrorUV GranitePrivate_ClampUV
// api-value-tested: Granite_Transform GranitePrivate_CalcMiplevelLinear
// api-value-tested: Granite_GetTextureDimensions GranitePrivate_CalcMiplevelAnisotropic
// api-value-tested: GranitePrivate_Pow2 Granite_ApplyResolutionOffset
// api-value-tested: GranitePrivate_CalculateCubemapCoordinates GranitePrivate_PackTileId
// api-value-tested: GranitePrivate_UnpackTileId Granite_PackTileId Granite_DebugPackedTileId64
// api-value-tested: Granite_MergeResolveOutputs Granite_UnpackNormal uie_gamma_to_linear
// api-value-tested: uie_linear_to_gamma uie_unpack_float2 uie_ray_unit_circle_first_hit
// api-value-tested: uie_radial_address ComputeRelativeClipRectCoords TestForValue
// api-value-tested: uie_decode_shader_info_texel_pos uie_get_border_offset DecodeSNorm16
// api-value-tested: GetIndirectVertexID GetIndirectInstanceID GetIndirectInstanceID_Base
// api-value-tested: GetCommandID GetIndirectVertexID_Base
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string>

#include "FormulaComparison.h"
#include "QuadDrawTest.h"
#include "varc/reader/Pack.h"
#include "varc/reader/PassView.h"
#include "varc/reader/ShaderView.h"
#include "varc/render/BuiltinTextures.h"

namespace varc::render {
namespace {

constexpr uint32_t kSize = 32;
using Vec4 = std::array<double, 4>;
using Formula = std::function<Vec4(double u, double v)>;

double frac(double x) { return x - std::floor(x); }
double clamp01(double x) { return std::min(std::max(x, 0.0), 1.0); }
double srgbToLinear(double x) {
    return x <= 0.04045 ? x / 12.92 : std::pow((x + 0.055) / 1.055, 2.4);
}
double linearToSrgb(double x) {
    return x <= 0.0031308 ? x * 12.92 : 1.055 * std::pow(x, 1.0 / 2.4) - 0.055;
}

// Exit point of the ray s + t d (t > 0) from the unit circle.
std::array<double, 2> circleExit(std::array<double, 2> s, std::array<double, 2> d) {
    double a = d[0] * d[0] + d[1] * d[1], b = 2 * (s[0] * d[0] + s[1] * d[1]);
    double c = s[0] * s[0] + s[1] * s[1] - 1;
    double t = (-b + std::sqrt(b * b - 4 * a * c)) / (2 * a);
    return {s[0] + t * d[0], s[1] + t * d[1]};
}

// The Vulkan specification's cube-map face selection (major axis; ties to x, then y) and face
// coordinates, with the derivative of the s coordinate plus that of t along |dv|.
Vec4 cubeFace(std::array<double, 3> r, std::array<double, 3> dv) {
    double ax = std::abs(r[0]), ay = std::abs(r[1]), az = std::abs(r[2]);
    int face;
    double sc, tc, ma, dsc, dtc, dma;
    if (ax >= ay && ax >= az) {
        face = r[0] >= 0 ? 0 : 1;
        double sgn = r[0] >= 0 ? -1 : 1;
        sc = sgn * r[2], tc = -r[1], ma = r[0], dsc = sgn * dv[2], dtc = -dv[1], dma = dv[0];
    } else if (ay >= az) {
        face = r[1] >= 0 ? 2 : 3;
        double sgn = r[1] >= 0 ? 1 : -1;
        sc = r[0], tc = sgn * r[2], ma = r[1], dsc = dv[0], dtc = sgn * dv[2], dma = dv[1];
    } else {
        face = r[2] >= 0 ? 4 : 5;
        double sgn = r[2] >= 0 ? 1 : -1;
        sc = sgn * r[0], tc = -r[1], ma = r[2], dsc = sgn * dv[0], dtc = -dv[1], dma = dv[2];
    }
    double m = std::abs(ma), dm = ma >= 0 ? dma : -dma;
    double ds = 0.5 * (dsc * m - sc * dm) / (m * m), dt = 0.5 * (dtc * m - tc * dm) / (m * m);
    return {face / 5.0, 0.5 * (sc / m + 1), 0.5 * (tc / m + 1), ds + dt};
}

class LongtailApiValueTest : public testing::QuadDrawTest {
protected:
    LongtailApiValueTest() : QuadDrawTest(kSize) {}

    // Draws |keyword|'s variant and compares every pixel's first |channels| channels with
    // |formula| within |absolute| + |relative| * |expected|; reports the worst pixel.
    void expectFormula(const std::string& keyword, const Formula& formula, int channels,
                       double absolute, double relative) {
        reader::PassView pass = *mPack->findShader("Test/LongtailApiValues")->pass(0);
        const BuiltinTextures& builtin = *mTextures;
        TextureLookup textures = [&builtin](std::string_view, pack::ResourceDim dim) {
            return builtin.named("white", dim);
        };
        image::Image image = drawQuad(pass, {keyword}, {}, textures);
        ASSERT_EQ(image.width(), kSize) << keyword;
        testing::FormulaComparison result =
            testing::compareWithFormula(image, formula, channels, absolute, relative);
        EXPECT_LE(result.worst, 1.0) << keyword << ": worst " << result.where;
        EXPECT_GT(result.largest, 0.05) << keyword << ": the expected values are all near zero";
    }
};

// Address modes and the streaming texture's transform (scale (0.5, 2), offset (0.25, -1)).
TEST_F(LongtailApiValueTest, GraniteAddressModes) {
    expectFormula(
        "LT_GRANITE_UV",
        [](double u, double v) {
            double x = 4 * u - 2, y = 3 * v - 1;
            return Vec4{frac(x), 1 - std::abs(frac(y * 0.5) * 2 - 1), clamp01(x), y * 2 - 1};
        },
        4, 1e-5, 1e-4);
}

// Mip levels of a 256 x 128 texture for gradients dx = (0.01 u, 0), dy = (0, 0.004 v + 0.0005):
// linear log2 of the longer footprint; anisotropic log2(longer / min(longer / shorter, 4)).
TEST_F(LongtailApiValueTest, GraniteMipLevels) {
    expectFormula(
        "LT_GRANITE_MIP",
        [](double u, double v) {
            double px = 0.01 * u * 256, py = (0.004 * v + 0.0005) * 128;
            double longer = std::max(px, py), shorter = std::min(px, py);
            double n = std::min(longer / shorter, 4.0);
            return Vec4{std::log2(longer), std::log2(longer / n),
                        std::exp2(std::floor(8 * u)) / 256, 2 * (0.5 + u)};
        },
        4, 1e-4, 1e-4);
}

TEST_F(LongtailApiValueTest, GraniteCubeFaces) {
    expectFormula(
        "LT_GRANITE_CUBE",
        [](double u, double v) {
            return cubeFace({4 * u - 2, 4 * v - 1.9, 1.05}, {0.1, 0.05, 0.02});
        },
        4, 1e-5, 1e-4);
}

// Tile ids round-trip through their 8-bit packing; the debug colour is (x mod 64) / 63; merged
// resolve outputs alternate in a checkerboard of pixels.
TEST_F(LongtailApiValueTest, GraniteTilesAndResolve) {
    expectFormula(
        "LT_GRANITE_TILE",
        [](double u, double v) {
            double tx = std::floor(200 * u), ty = std::floor(100 * v);
            int px = static_cast<int>(std::floor(u * kSize)),
                py = static_cast<int>(std::floor(v * kSize));
            return Vec4{tx / 255 + 7.0 / 1000, ty / 255, std::fmod(tx, 64.0) / 63,
                        (px + py) % 2 == 0 ? u : v};
        },
        4, 1e-5, 1e-4);
}

// Two-channel normals: xy = (rg * 2 - 1) * scale, z = sqrt(1 - |xy|^2) (0 past the unit disc).
TEST_F(LongtailApiValueTest, GraniteNormals) {
    expectFormula(
        "LT_GRANITE_NORMAL",
        [](double u, double v) {
            double s = 0.5 + u, x = (2 * u - 1) * s, y = (2 * v - 1) * s;
            double x1 = 2 * v - 1, y1 = 2 * u - 1;
            return Vec4{x, y, std::sqrt(1 - clamp01(x * x + y * y)),
                        std::sqrt(1 - clamp01(x1 * x1 + y1 * y1))};
        },
        4, 1e-4, 1e-4);
}

// Vertex colours to linear and back (sRGB curves); two 16-bit integers from four bytes.
TEST_F(LongtailApiValueTest, UIElementsColours) {
    expectFormula(
        "LT_UIE_COLOR",
        [](double u, double v) {
            double r = std::round(255 * u), g = std::round(255 * v), b = std::round(255 * (1 - u)),
                   a = std::round(127.5);
            return Vec4{srgbToLinear(u), linearToSrgb(v), (r + 256 * g) / 65535,
                        (b + 256 * a) / 65535};
        },
        4, 1e-4, 1e-3);
}

// Ray exits from the unit circle, radial gradient parameters (distance from the focus over the
// distance from the focus to the circle), and clip-rect relative coordinates.
TEST_F(LongtailApiValueTest, UIElementsGeometry) {
    expectFormula(
        "LT_UIE_GEOMETRY",
        [](double u, double v) {
            double angle = 6.2831853 * u;
            auto hit =
                circleExit({(u - 0.5) * 0.8, (v - 0.5) * 0.8}, {std::cos(angle), std::sin(angle)});
            double px = (2 * u - 1) * 0.7 - 0.2, py = (2 * v - 1) * 0.7 + 0.1,
                   len = std::hypot(px, py);
            auto edge = circleExit({0.2, -0.1}, {px / len, py / len});
            double radial = len / std::hypot(edge[0] - 0.2, edge[1] + 0.1);
            return Vec4{hit[0], hit[1], radial, (v - 0.2) / 0.4};
        },
        4, 1e-4, 1e-3);
}

// Float bit sets decoded from the top bit down; shader-info texels (32-wide pages, 3 rows per
// entry); border offsets grown to at least 0.05 on each axis that may shrink.
TEST_F(LongtailApiValueTest, UIElementsFlags) {
    expectFormula(
        "LT_UIE_FLAGS",
        [](double u, double v) {
            double flags = std::floor(16 * u), bit8 = flags >= 8 ? 1 : 0;
            flags -= 8 * bit8;
            double bit4 = flags >= 4 ? 1 : 0;
            flags -= 4 * bit4;
            double id = std::floor(100 * v), pageX = std::floor(3 * u), pageY = std::floor(2 * v);
            double dx = (u - 0.5) * 0.2, dy = (v - 0.5) * 0.2;
            auto grow = [](double d) {
                return (d > 0 ? 1 : (d < 0 ? -1 : 0)) * std::max(std::abs(d), 0.05);
            };
            return Vec4{bit8 + 2 * bit4 + flags / 16, (pageX * 32 + std::fmod(id, 32.0)) / 100,
                        (pageY * 32 * 3 + std::floor(id / 32) * 3) / 1000,
                        grow(dx) + (v > 0.5 ? dy : grow(dy))};
        },
        4, 1e-5, 1e-4);
}

// Signed 16-bit normalised decoding; on Vulkan the vertex and instance indices include the
// draw's first vertex / instance, which the relative ids remove (the base command id is 0).
TEST_F(LongtailApiValueTest, IndirectIdsAndSnorm) {
    expectFormula(
        "LT_INDIRECT_RT",
        [](double u, double v) {
            double bits = std::floor(65535 * u), value = bits >= 32768 ? bits - 65536 : bits;
            double k = std::floor(100 * u), n = std::floor(10 * v);
            return Vec4{std::max(value / 32767, -1.0), k / 100 + n / 10, k / 100 + n / 10,
                        std::floor(4 * v) / 4 + k / 1000};
        },
        4, 1e-5, 1e-4);
}

}  // namespace
}  // namespace varc::render
