// SPDX-License-Identifier: Apache-2.0
// Value tests of UnityCG.cginc's fog macros (issue #27, docs/BUILTIN_API.md): each group of
// tests/vulkan/helpers/FogMacroValues.shader runs on lavapipe in every fog mode of
// multi_compile_fog and is compared with the fog Unity's manual documents. unity_FogParams is
// (density / sqrt(ln 2), density / ln 2, -1 / (end - start), end / (end - start)); the fog
// factor of a fragment at fog coordinate (eye depth) d is (end - d) / (end - start) for
// FOG_LINEAR, exp(-density d) for FOG_EXP and exp(-(density d)^2) for FOG_EXP2; the colour
// becomes lerp(fogColour, colour, saturate(factor)) in rgb, alpha untouched, and without a fog
// keyword nothing changes. scripts/builtin-api.py counts the macros named on the
// api-value-tested lines below as implemented.
//
// api-value-tested: UNITY_FOG_COORDS UNITY_FOG_COORDS_PACKED UNITY_TRANSFER_FOG UNITY_APPLY_FOG
// api-value-tested: UNITY_APPLY_FOG_COLOR UNITY_CALC_FOG_FACTOR UNITY_CALC_FOG_FACTOR_RAW
// api-value-tested: UNITY_FOG_LERP_COLOR UNITY_EXTRACT_FOG UNITY_EXTRACT_FOG_FROM_TSPACE
// api-value-tested: UNITY_EXTRACT_FOG_FROM_WORLD_POS UNITY_EXTRACT_FOG_FROM_EYE_VEC
// api-value-tested: UNITY_TRANSFER_FOG_COMBINED_WITH_TSPACE
// api-value-tested: UNITY_TRANSFER_FOG_COMBINED_WITH_EYE_VEC
// api-value-tested: UNITY_TRANSFER_FOG_COMBINED_WITH_WORLD_POS
// api-value-tested: UNITY_EXTRACT_TBN UNITY_EXTRACT_TBN_0 UNITY_EXTRACT_TBN_1 UNITY_EXTRACT_TBN_2
// api-value-tested: UNITY_EXTRACT_TBN_T UNITY_EXTRACT_TBN_N UNITY_EXTRACT_TBN_B
// api-value-tested: UNITY_CORRECT_TBN_B_SIGN UNITY_RECONSTRUCT_TBN
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
constexpr double kDensity = 0.05, kStart = 4.0, kEnd = 30.0;
const glm::vec4 kFogColour(0.3f, 0.6f, 0.9f, 1.0f);
using Vec4 = std::array<double, 4>;
using Formula = std::function<Vec4(double u, double v)>;
// The fog factor of a mode at fog coordinate d (not saturated); "" is no fog: factor 1.
using FogFactor = std::function<double(double d)>;

struct FogMode {
    std::string keyword;
    FogFactor factor;
};
const std::array<FogMode, 4> kModes = {{
    {"", [](double) { return 1.0; }},
    {"FOG_LINEAR", [](double d) { return (kEnd - d) / (kEnd - kStart); }},
    {"FOG_EXP", [](double d) { return std::exp(-kDensity * d); }},
    {"FOG_EXP2", [](double d) { return std::exp(-(kDensity * d) * (kDensity * d)); }},
}};

double depthAt(double u) { return 2.0 + 30.0 * u; }  // the fog coordinate the shader makes
double blend(double fog, double colour, double factor) {
    double t = std::clamp(factor, 0.0, 1.0);
    return fog + (colour - fog) * t;
}

class FogMacroValueTest : public testing::QuadDrawTest {
protected:
    FogMacroValueTest() : QuadDrawTest(kSize) {}

    // Draws |group| in every fog mode and compares with |formula(mode)|.
    void expectInEveryMode(const std::string& group,
                           const std::function<Formula(const FogMode&)>& formula) {
        reader::PassView pass = *mPack->findShader("Test/FogMacroValues")->pass(0);
        const BuiltinTextures& builtin = *mTextures;
        TextureLookup textures = [&builtin](std::string_view, pack::ResourceDim dim) {
            return builtin.named("white", dim);
        };
        ShaderValues values;
        values.set("unity_FogParams",
                   glm::vec4(static_cast<float>(kDensity / std::sqrt(std::log(2.0))),
                             static_cast<float>(kDensity / std::log(2.0)),
                             static_cast<float>(-1.0 / (kEnd - kStart)),
                             static_cast<float>(kEnd / (kEnd - kStart))));
        values.set("unity_FogColor", kFogColour);
        for (const FogMode& mode : kModes) {
            std::vector<std::string> keywords = {group};
            if (!mode.keyword.empty()) keywords.push_back(mode.keyword);
            image::Image image = drawQuad(pass, keywords, values, textures);
            ASSERT_EQ(image.width(), kSize) << group << " " << mode.keyword;
            testing::FormulaComparison result =
                testing::compareWithFormula(image, formula(mode), 4, 2e-5, 2e-4);
            EXPECT_LE(result.worst, 1.0) << group << " " << mode.keyword << ": " << result.where;
            EXPECT_GT(result.largest, 0.1) << group << " " << mode.keyword;
        }
    }
};

// UNITY_FOG_COORDS + UNITY_TRANSFER_FOG + UNITY_APPLY_FOG: rgb towards unity_FogColor.
TEST_F(FogMacroValueTest, ApplyFog) {
    expectInEveryMode("FG_APPLY", [](const FogMode& mode) -> Formula {
        return [mode](double u, double v) {
            double f = mode.factor(depthAt(u));
            return Vec4{blend(kFogColour.r, u, f), blend(kFogColour.g, v, f),
                        blend(kFogColour.b, 0.5, f), 0.8};
        };
    });
}

// The raw factor (unsaturated: linear fog exceeds 1 before the start distance; 0 without fog),
// UNITY_APPLY_FOG_COLOR towards a given colour, and UNITY_EXTRACT_FOG + UNITY_CALC_FOG_FACTOR +
// UNITY_FOG_LERP_COLOR towards white (with a fixed factor 0.25 when there is no fog).
TEST_F(FogMacroValueTest, FactorAndExplicitBlend) {
    expectInEveryMode("FG_FACTOR", [](const FogMode& mode) -> Formula {
        return [mode](double u, double v) {
            double d = depthAt(u);
            bool fog = !mode.keyword.empty();
            double f = mode.factor(d);
            return Vec4{fog ? mode.factor(0.5 * d) : 0.0, blend(0.9, v, f),
                        blend(1.0, 0.5, fog ? f : 0.25), 0.8};
        };
    });
}

// UNITY_FOG_COORDS_PACKED(1, float4): the fog coordinate is x, the caller's data in yzw
// survives; without fog the member keeps what the vertex stage wrote.
TEST_F(FogMacroValueTest, PackedCoordinate) {
    expectInEveryMode("FG_PACKED", [](const FogMode& mode) -> Formula {
        return [mode](double u, double v) {
            double d = depthAt(u);
            bool fog = !mode.keyword.empty();
            return Vec4{blend(kFogColour.r, u, mode.factor(d)), v, 0.75, fog ? d : 7.0};
        };
    });
}

// Generated surface code's packing: the coordinate rides in tSpace2.y, worldPos.w or eyeVec.w
// (each given another depth here) and is extracted from there; the other members are intact.
TEST_F(FogMacroValueTest, CombinedPacking) {
    expectInEveryMode("FG_COMBINED", [](const FogMode& mode) -> Formula {
        return [mode](double u, double) {
            double d = depthAt(u);
            return Vec4{blend(kFogColour.r, u, mode.factor(d)),
                        blend(kFogColour.r, u, mode.factor(0.5 * d)),
                        blend(kFogColour.r, u, mode.factor(0.25 * d)), 1.8};
        };
    });
}

// The tangent frame of generated surface code: rows tSpaceN = (tangent.N, binormal.N,
// normal.N); with fog the binormal's z carries the fog coordinate, and UNITY_RECONSTRUCT_TBN
// rebuilds it as +-cross(normal, tangent) with the sign of the binormal that is left, so the
// rows come back for both handednesses (the right half is mirrored). Without fog it reads the
// rows as they are (UNITY_EXTRACT_TBN).
TEST_F(FogMacroValueTest, TangentFrameUnpacking) {
    expectInEveryMode("FG_TBN", [](const FogMode&) -> Formula {
        return [](double u, double v) {
            double len = std::sqrt((u - 0.5) * (u - 0.5) + (v - 0.5) * (v - 0.5) + 1.0);
            glm::dvec3 n((u - 0.5) / len, (v - 0.5) / len, 1.0 / len);
            glm::dvec3 t = glm::normalize(glm::cross(glm::dvec3(0, 1, 0), n));
            glm::dvec3 b = glm::cross(n, t) * (u < 0.5 ? 1.0 : -1.0);
            return Vec4{b.z, b.x, n.y, t.z};
        };
    });
}

}  // namespace
}  // namespace varc::render
