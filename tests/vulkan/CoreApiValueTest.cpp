// SPDX-License-Identifier: Apache-2.0
// Value tests of the core built-in API added for issue #27 (docs/BUILTIN_API.md): each group runs
// on lavapipe over a grid of inputs (tests/vulkan/helpers/CoreApiValues.shader, pixel centre
// (u, v) as input) and is compared with the formula computed here. scripts/builtin-api.py counts
// the functions named on the api-value-tested lines below as implemented.
//
// api-value-tested: tex2Dproj tex2DprojShadow SmithVisibilityTerm SmithBeckmannVisibilityTerm
// api-value-tested: NDFBlinnPhongNormalizedTerm PerceptualRoughnessToSpecPower FresnelLerpFast
// api-value-tested: Pow4 Pow5 UnityStereoScreenSpaceUVAdjustInternal VertexLight Hammersley2d
// api-value-tested: RadicalInverse_VdC ReverseBits32 GetLocalFrame
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "FormulaComparison.h"
#include "QuadDrawTest.h"
#include "varc/scene/LightTextures.h"

namespace varc::render {
namespace {

constexpr uint32_t kSize = 32;
constexpr double kPi = 3.14159265358979323846;
using Vec4 = std::array<double, 4>;
using Formula = std::function<Vec4(double u, double v)>;

// The falloff table as the GPU samples it along u (every channel holds it).
double falloffAt(double t) {
    static const std::vector<uint16_t> table = scene::falloffTable();
    return scene::sampleFalloffTable(table, static_cast<float>(t));
}
double smithVisibility(double nl, double nv, double k) {
    return 1.0 / ((nl * (1 - k) + k) * (nv * (1 - k) + k) + 1e-5);
}

class CoreApiValueTest : public testing::QuadDrawTest {
protected:
    CoreApiValueTest() : QuadDrawTest(kSize) {}

    // Draws |keyword| with the falloff table as _ApiFalloff, white elsewhere, and compares the
    // first |channels| channels of every pixel with |formula| within |absolute| + |relative| *
    // |expected|; reports the worst pixel.
    void expectFormula(const std::string& keyword, const Formula& formula, int channels,
                       double absolute, double relative) {
        reader::PassView pass = *mPack->findShader("Test/CoreApiValues")->pass(0);
        const BuiltinTextures& builtin = *mTextures;
        TextureLookup textures = [&builtin](std::string_view name, pack::ResourceDim dim) {
            return name == "_ApiFalloff" ? std::optional(builtin.falloff())
                                         : builtin.named("white", dim);
        };
        image::Image image = drawQuad(pass, {keyword}, {}, textures);
        ASSERT_EQ(image.width(), kSize) << keyword;
        testing::FormulaComparison result =
            testing::compareWithFormula(image, formula, channels, absolute, relative);
        EXPECT_LE(result.worst, 1.0) << keyword << ": worst " << result.where;
    }
};

// tex2Dproj divides xy by the last component (3- and 4-component forms); tex2DprojShadow
// compares the (projected) depth with the map's (white: 1), 1 = lit.
TEST_F(CoreApiValueTest, ProjectiveSampling) {
    expectFormula(
        "CORE_PROJ",
        [](double u, double v) {
            return Vec4{falloffAt(u), falloffAt(v), 1.5 * u <= 1.0 ? 1.0 : 0.0,
                        2.0 * v <= 1.0 ? 1.0 : 0.0};
        },
        4, 3e-3, 0);
}

TEST_F(CoreApiValueTest, BrdfTerms) {
    expectFormula(
        "CORE_BRDF",
        [](double u, double v) {
            double m = (0.05 + 0.9 * u) * (0.05 + 0.9 * u);
            return Vec4{smithVisibility(u, v, 0.2 + 0.5 * u),
                        smithVisibility(u, v, (0.1 + 0.8 * v) * std::sqrt(2.0 / kPi)) * 0.25,
                        (3.0 + 60.0 * v) / (2.0 * kPi) * std::pow(u, 1.0 + 60.0 * v),
                        std::max(2.0 / std::max(1e-4, m * m) - 2.0, 1e-4)};
        },
        4, 1e-5, 2e-4);
    expectFormula(
        "CORE_BRDF_FRESNEL",
        [](double u, double v) {
            double t = std::pow(1.0 - u * v, 4.0);
            auto lerp = [t](double a, double b) { return a + (b - a) * t; };
            return Vec4{lerp(0.04, 1.0), lerp(0.5, v), lerp(u, 0.2),
                        std::pow(v, 4) + std::pow(u, 5) + std::pow(v, 4) + std::pow(u, 5) +
                            std::pow(u, 4) + std::pow(v, 5)};
        },
        4, 1e-5, 1e-4);
}

// uv * scale + offset, for a float4 on both halves.
TEST_F(CoreApiValueTest, StereoUvAdjustment) {
    expectFormula(
        "CORE_STEREO",
        [](double u, double v) {
            return Vec4{u * 0.5 + 0.25, v * 2.0 - 1.0, v * 3.0 + 0.5, -u + 0.125};
        },
        4, 1e-6, 1e-5);
}

// texture * diffuse + specular * texture alpha; alpha = texture alpha * diffuse alpha.
TEST_F(CoreApiValueTest, VertexLitCombine) {
    expectFormula(
        "CORE_VERTEX_LIT",
        [](double u, double v) {
            double f = falloffAt(u);
            return Vec4{f * u + v * f, f * v + 0.2 * f, f * 0.5 + u * f, f * v};
        },
        4, 3e-3, 0);
}

// The radical inverse mirrors the index's bits about the binary point.
double radicalInverse(uint32_t bits) {
    double result = 0, weight = 0.5;
    for (int k = 0; k < 32; ++k, weight *= 0.5) {
        if (bits & (1u << k)) result += weight;
    }
    return result;
}

TEST_F(CoreApiValueTest, LowDiscrepancyPoints) {
    expectFormula(
        "CORE_HAMMERSLEY",
        [](double u, double v) {
            auto index = static_cast<uint32_t>(u * 32.0) * 32u + static_cast<uint32_t>(v * 32.0);
            // ReverseBits32(i) >> 22: the 10-bit index mirrored, i.e. the radical inverse * 1024.
            return Vec4{index / 1024.0, radicalInverse(index), radicalInverse(index << 7),
                        std::round(radicalInverse(index) * 1024.0)};
        },
        4, 1e-6, 1e-6);
}

// tangentX = normalize(cross(z, N)) (|N.z| < 0.999), tangentY = cross(N, tangentX): orthonormal.
TEST_F(CoreApiValueTest, LocalFrame) {
    expectFormula(
        "CORE_FRAME",
        [](double u, double v) {
            double n[3] = {u - 0.5, v - 0.5, 0.8 - u};
            double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            for (double& c : n) c /= len;
            double tx[3] = {-n[1], n[0], 0};  // cross((0, 0, 1), n)
            double tl = std::sqrt(tx[0] * tx[0] + tx[1] * tx[1]);
            tx[0] /= tl;
            tx[1] /= tl;
            double tyz = n[0] * tx[1] - n[1] * tx[0];  // cross(n, tx).z
            return Vec4{tx[0], tx[1], tyz, 0.0};
        },
        4, 2e-5, 1e-4);
}

}  // namespace
}  // namespace varc::render
