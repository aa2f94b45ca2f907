// SPDX-License-Identifier: Apache-2.0
// Value tests of UnityUIE.cginc's fragment helpers (issue #27, docs/BUILTIN_API.md): each group
// runs on lavapipe over a grid of inputs (tests/vulkan/helpers/UieValues.shader, pixel centre
// (u, v) as input) and is compared with the helper's documented meaning computed here: float
// equality within 1e-4, a pixel's footprint |fwidth(uv)|, coverage of a signed distance
// antialiased over that footprint (0.5 on the edge), a rounded corner's coverage (inside the
// outer arc, outside the inner one), snapping to whole pixels, and the texture slots and
// shader-info texels read back. scripts/builtin-api.py counts the functions named on the
// api-value-tested lines below as implemented.
//
// api-value-tested: fpEqual pixelDist sdf ComputeCoverage sd_to_coverage uie_snap_to_integer_pos
// api-value-tested: FindTextureSlot GetTextureInfo SampleTextureSlot SampleShaderInfo
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "FormulaComparison.h"
#include "QuadDrawTest.h"
#include "varc/scene/LightTextures.h"

namespace varc::render {
namespace {

constexpr uint32_t kSize = 32;
using Vec4 = std::array<double, 4>;
using Formula = std::function<Vec4(double u, double v)>;

double saturate(double x) { return std::clamp(x, 0.0, 1.0); }
// |fwidth(k uv)| over the 32-pixel target: k / 32 on each axis.
double footprint(double k) { return std::sqrt(2.0) * k / 32.0; }
// The texture bound to slot i (_Texture<i>) and its r + 2 g.
const char* const kSlotTextures[8] = {"black", "white", "red",   "gray",
                                      "bump",  "white", "black", "red"};
double slotValue(int i) {
    const double gray = 128.0 / 255.0;
    const double values[8] = {0, 3, 1, 3 * gray, 3 * gray, 3, 0, 1};
    return values[i];
}

class UieValueTest : public testing::QuadDrawTest {
protected:
    UieValueTest() : QuadDrawTest(kSize) {}

    void expectFormula(const std::string& keyword, const ShaderValues& values,
                       const Formula& formula, double absolute, double relative) {
        const BuiltinTextures& builtin = *mTextures;
        TextureLookup textures = [&builtin](std::string_view name, pack::ResourceDim dim) {
            if (name == "_ShaderInfoTex") return std::optional(builtin.falloff());
            for (int i = 0; i < 8; ++i) {
                if (name == "_Texture" + std::to_string(i))
                    return builtin.named(kSlotTextures[i], dim);
            }
            return builtin.named("white", dim);
        };
        expectPassFormula("Test/UieValues", keyword, values, textures, formula, 4, absolute,
                          relative);
    }
};

TEST_F(UieValueTest, EqualityFootprintAndCoverage) {
    expectFormula(
        "UE_BASICS", {},
        [](double u, double v) {
            double equal = (std::abs(u - v) < 1e-4 ? 1.0 : 0.0) + 2.0;
            double outer = saturate(0.5 - (1.2 * std::hypot(u, v) - 1.0) / footprint(1.2));
            double inner = saturate(0.5 + (1.5 * std::hypot(u, v) - 1.0) / footprint(1.5));
            return Vec4{equal, footprint(3.0), saturate((4 * u - 0.5) / (4.0 / 32.0) + 0.5),
                        outer * inner};
        },
        2e-5, 1e-4);
}

// Text coverage: (sd * scale + dilation) / (footprint in texels + softness) + 0.5, saturated;
// snapping rounds clip-space xy to whole pixels of a viewport 2 * _ClipSpaceParams.xy wide.
TEST_F(UieValueTest, TextCoverageAndSnapping) {
    ShaderValues values;
    values.set("_ClipSpaceParams", glm::vec4(10.0f, 10.0f, 0.1f, 0.1f));
    expectFormula(
        "UE_TEXT", values,
        [](double u, double v) {
            double texels = footprint(2.0) * 64.0;
            auto cover = [texels](double sd, double dilate, double soft) {
                return saturate((sd * 2.0 + dilate) / (texels + soft) + 0.5);
            };
            auto snap = [](double c) { return std::floor(c * 10.0 + 0.5) * 0.1; };
            return Vec4{cover(u - 0.5, 0.1, 0), cover(u - 0.5, 0.1, 0) + 10 * cover(v - 0.5, 0, 1),
                        cover(0, -0.1, 2), snap(2 * u - 1) + 10 * snap(2 * v - 1)};
        },
        2e-5, 1e-4);
}

// Slot i's texture id is _TextureInfo[2 i].x (10 + 5 i here), its texel size .zw; an id no slot
// has finds slot 0. SampleTextureSlot reads _Texture<i>; SampleShaderInfo reads texel (x, y) of
// _ShaderInfoTex (the falloff table here) at its centre.
TEST_F(UieValueTest, TextureSlotsAndShaderInfo) {
    std::vector<glm::vec4> info(16, glm::vec4(0.0f));
    for (int i = 0; i < 8; ++i) {
        float slot = static_cast<float>(i);
        info[2 * i] = glm::vec4(10.0f + 5.0f * slot, 0.0f, (slot + 1.0f) / 16.0f, 0.0f);
    }
    ShaderValues values;
    values.setArray("_TextureInfo", info);
    values.set("_ShaderInfoTex_TexelSize", glm::vec4(1.0f / 1024.0f, 1.0f, 1024.0f, 1.0f));
    static const std::vector<uint16_t> table = scene::falloffTable();
    expectFormula(
        "UE_SLOTS", values,
        [](double u, double v) {
            int wanted = static_cast<int>(std::floor(10 * u));
            int slot = wanted <= 7 ? wanted : 0;
            double texel = std::floor(u * 32) * 32 + 16;
            double falloff =
                scene::sampleFalloffTable(table, static_cast<float>((texel + 0.5) / 1024.0));
            return Vec4{slot + (slot + 1) / 16.0, slotValue(static_cast<int>(std::floor(8 * v))),
                        10.0 + 5.0 * slot, falloff};
        },
        3e-3, 1e-5);
}

}  // namespace
}  // namespace varc::render
