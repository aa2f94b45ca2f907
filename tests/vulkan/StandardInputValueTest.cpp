// SPDX-License-Identifier: Apache-2.0
// Value tests of the Standard shader's material inputs (UnityStandardInput.cginc) and light
// helpers (UnityStandardCore.cginc) (issue #27, docs/BUILTIN_API.md), run on lavapipe by
// tests/vulkan/helpers/StandardInputValues.shader with solid textures of known texels and
// compared with the Standard shader's documented material model: albedo = _Color * _MainTex,
// alpha = _Color.a * _MainTex.a, occlusion = lerp(1, _OcclusionMap.g, _OcclusionStrength),
// emission = _EmissionMap * _EmissionColor (black without _EMISSION), metallic / smoothness from
// _Metallic / _Glossiness or _MetallicGlossMap.ra * (1, _GlossMapScale), the parallax offset of
// _ParallaxMap.g, the normal map scaled by _BumpScale, uv0 / uv1 (by _UVSec) through the _ST
// transforms; the main light is _LightColor0 from _WorldSpaceLightPos0, an additive light is
// attenuated and normalised, opaque forward output has alpha 1. scripts/builtin-api.py counts
// the names on the api-value-tested lines below as implemented.
//
// api-value-tested: TexCoords Albedo Alpha Occlusion SpecularGloss MetallicGloss Emission
// api-value-tested: Parallax NormalInTangentSpace MainLight AdditiveLight DummyLight
// api-value-tested: ZeroIndirect OutputForward
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
constexpr double kGray = 128.0 / 255.0;  // the "gray" texture's texel (UNORM)
using Vec4 = std::array<double, 4>;
using Formula = std::function<Vec4(double u, double v)>;

ShaderValues materialValues() {
    ShaderValues values;
    values.set("_Color", glm::vec4(0.8f, 0.6f, 0.4f, 0.7f));
    values.set("_MainTex_ST", glm::vec4(2.0f, 3.0f, 0.1f, 0.2f));
    values.set("_DetailAlbedoMap_ST", glm::vec4(0.5f, 1.5f, -0.1f, 0.3f));
    values.set("_UVSec", 1.0f);
    values.set("_OcclusionStrength", 0.6f);
    values.set("_SpecColor", glm::vec4(0.2f, 0.35f, 0.5f, 1.0f));
    values.set("_Metallic", 0.25f);
    values.set("_Glossiness", 0.45f);
    values.set("_GlossMapScale", 0.8f);
    values.set("_EmissionColor", glm::vec4(1.5f, 0.75f, 0.2f, 1.0f));
    values.set("_Parallax", 0.05f);
    values.set("_BumpScale", 1.7f);
    values.set("_LightColor0", glm::vec4(0.9f, 0.7f, 1.3f, 1.0f));
    values.set("_WorldSpaceLightPos0", glm::vec4(0.3f, 0.5f, 0.8f, 0.0f));
    return values;
}

class StandardInputValueTest : public testing::QuadDrawTest {
protected:
    StandardInputValueTest() : QuadDrawTest(kSize) {}

    void expectFormula(const std::string& keyword, const Formula& formula) {
        reader::PassView pass = *mPack->findShader("Test/StandardInputValues")->pass(0);
        const BuiltinTextures& builtin = *mTextures;
        TextureLookup textures = [&builtin](std::string_view name, pack::ResourceDim dim) {
            if (name == "_BumpMap") return builtin.named("bump", dim);
            if (name == "_MainTex" || name == "_OcclusionMap" || name == "_EmissionMap" ||
                name == "_ParallaxMap" || name == "_MetallicGlossMap")
                return builtin.named("gray", dim);
            return builtin.named("white", dim);
        };
        image::Image image = drawQuad(pass, {keyword}, materialValues(), textures);
        ASSERT_EQ(image.width(), kSize) << keyword;
        testing::FormulaComparison result =
            testing::compareWithFormula(image, formula, 4, 2e-5, 2e-4);
        EXPECT_LE(result.worst, 1.0) << keyword << ": worst " << result.where;
        EXPECT_GT(result.largest, 0.1) << keyword;
    }
};

// xy: uv0 through _MainTex_ST; zw: uv1 (_UVSec = 1) through _DetailAlbedoMap_ST.
TEST_F(StandardInputValueTest, TexCoords) {
    expectFormula("SI_TEXCOORDS", [](double u, double v) {
        return Vec4{2 * u + 0.1, 3 * v + 0.2, 0.5 * v - 0.1, 1.5 * u + 0.3};
    });
}

// Without map keywords: albedo.g, alpha, occlusion; specular.g + metallic + emission (black).
TEST_F(StandardInputValueTest, SurfaceWithoutMaps) {
    expectFormula("SI_SURFACE", [](double, double) {
        return Vec4{0.6 * kGray, 0.7, 1 - 0.6 + kGray * 0.6, 0.35 + 0.25 + 0.0};
    });
}

// With _PARALLAXMAP, _EMISSION and _METALLICGLOSSMAP: the height kGray moves both uv pairs by
// the single-step offset; emission.g; smoothness = map alpha (1) * _GlossMapScale.
TEST_F(StandardInputValueTest, SurfaceWithMaps) {
    expectFormula("SI_MAPS", [](double u, double v) {
        double vx = u - 0.5, vy = v - 0.5, vz = 0.5;
        double len = std::sqrt(vx * vx + vy * vy + vz * vz);
        double shift = kGray * 0.05 - 0.05 / 2, z = vz / len + 0.42;
        double ox = shift * vx / len / z, oy = shift * vy / len / z;
        return Vec4{u + ox, 0.5 * v + oy, kGray * 0.75, 0.8};
    });
}

// _NORMALMAP: the bump texel rgb * 2 - 1 with xy scaled by _BumpScale; smoothness _Glossiness.
TEST_F(StandardInputValueTest, NormalAndGlossiness) {
    expectFormula("SI_NORMAL", [](double, double) {
        return Vec4{(2 * kGray - 1) * 1.7, (2 * kGray - 1) * 1.7, 1.0, 0.45};
    });
}

// Main light colour.g + direction.x; the additive light's normalised direction and colour *
// attenuation; opaque output alpha 1 plus the dummy light's direction.y (1), its black colour
// and the zero indirect light.
TEST_F(StandardInputValueTest, Lights) {
    expectFormula("SI_LIGHTS", [](double u, double v) {
        double len = std::sqrt((u - 0.5) * (u - 0.5) + (v - 0.5) * (v - 0.5) + 1.0);
        return Vec4{0.7 + 0.3, (u - 0.5) / len, 1.3 * (0.5 + 0.5 * u), 2.0};
    });
}

}  // namespace
}  // namespace varc::render
