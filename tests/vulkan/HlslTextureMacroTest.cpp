// SPDX-License-Identifier: Apache-2.0
// Value tests of HLSLSupport.cginc's texture and uniform-block macros (issue #27,
// docs/BUILTIN_API.md): tests/vulkan/helpers/HlslTextureMacros.shader declares textures with each
// macro and samples them with each sampling macro; this test uploads textures whose texels it
// knows (sampled nearest, so each result is one texel or a compare against one) and checks every
// pixel against the texel the macro's documented meaning selects. The texture-stack macros of
// UnityLegacyTextureStack.cginc sample the same textures. scripts/builtin-api.py counts
// the macros named on the api-value-tested lines below as implemented.
//
// api-value-tested: UNITY_DECLARE_TEX2D UNITY_DECLARE_TEX2D_NOSAMPLER UNITY_DECLARE_TEX2D_HALF
// api-value-tested: UNITY_DECLARE_TEX2D_FLOAT UNITY_DECLARE_TEX2D_NOSAMPLER_HALF
// api-value-tested: UNITY_DECLARE_TEX2D_NOSAMPLER_FLOAT UNITY_SAMPLE_TEX2D
// api-value-tested: UNITY_SAMPLE_TEX2D_SAMPLER UNITY_SAMPLE_TEX2D_LOD
// api-value-tested: UNITY_SAMPLE_TEX2D_SAMPLER_LOD UNITY_DECLARE_DEPTH_TEXTURE
// api-value-tested: UNITY_SAMPLE_DEPTH UNITY_DECLARE_SHADOWMAP UNITY_SAMPLE_SHADOW
// api-value-tested: UNITY_SAMPLE_SHADOW_PROJ UNITY_DECLARE_SCREENSPACE_TEXTURE
// api-value-tested: UNITY_SAMPLE_SCREENSPACE_TEXTURE UNITY_DECLARE_SCREENSPACE_SHADOWMAP
// api-value-tested: UNITY_SAMPLE_SCREEN_SHADOW UNITY_INITIALIZE_OUTPUT UNITY_POSITION
// api-value-tested: UNITY_DECLARE_TEX3D UNITY_DECLARE_TEX3D_HALF UNITY_DECLARE_TEX3D_FLOAT
// api-value-tested: UNITY_DECLARE_TEX3D_NOSAMPLER UNITY_SAMPLE_TEX3D UNITY_SAMPLE_TEX3D_LOD
// api-value-tested: UNITY_SAMPLE_TEX3D_SAMPLER UNITY_SAMPLE_TEX3D_SAMPLER_LOD
// api-value-tested: UNITY_DECLARE_TEXCUBE UNITY_DECLARE_TEXCUBE_NOSAMPLER UNITY_SAMPLE_TEXCUBE
// api-value-tested: UNITY_SAMPLE_TEXCUBE_LOD UNITY_SAMPLE_TEXCUBE_SAMPLER SampleCubeReflection
// api-value-tested: UNITY_SAMPLE_TEXCUBE_SAMPLER_LOD UNITY_ARGS_TEXCUBE UNITY_PASS_TEXCUBE
// api-value-tested: UNITY_ARGS_TEXCUBE_NOSAMPLER UNITY_PASS_TEXCUBE_SAMPLER
// api-value-tested: UNITY_PASS_TEXCUBE_SAMPLER_LOD UNITY_DECLARE_TEXCUBE_SHADOWMAP
// api-value-tested: UNITY_SAMPLE_TEXCUBE_SHADOW texCUBEproj CBUFFER_START GLOBAL_CBUFFER_START
// api-value-tested: CBUFFER_START_WITH_BINDING UNITY_INSTANCING_CBUFFER_SCOPE_BEGIN
// api-value-tested: DECL_WITH_BINDING MakeStackInfo MakeStackInfoLod GetResolveOutput
// api-value-tested: PrepareStack PrepareStackLod SampleStack SampleStackLod SampleStackNormal
// api-value-tested: SampleStackLodNormal gra_RcpCacheInTiles gra_BorderPixelsRcpCache
// api-value-tested: Granite_SetMaxAnisotropy GranitePrivate_TranslateCoord
// api-value-tested: GranitePrivate_DrawDebugTiles
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "FormulaComparison.h"
#include "QuadDrawTest.h"
#include "varc/vulkan/Sampler.h"
#include "varc/vulkan/Texture.h"

namespace varc::render {
namespace {

constexpr uint32_t kSize = 32;
using Vec4 = std::array<double, 4>;
using Formula = std::function<Vec4(double u, double v)>;

// The 2D texture (8 x 8, mipmapped by averaging): texel (x, y) of level 0 is
// ((x + 8 y) / 64, x / 8, y / 8, 1 - x / 16). Being linear in (x, y), a texel of level L (the
// mean of a 2^L square) is the same formula at the square's mean index.
Vec4 texel2D(double x, double y) { return {(x + 8 * y) / 64, x / 8, y / 8, 1 - x / 16}; }
Vec4 sample2D(double s, double t, int level) {
    double n = 8.0 / (1 << level), scale = 1 << level;
    auto mean = [&](double c) { return (std::floor(c * n) + 0.5) * scale - 0.5; };
    return texel2D(mean(s), mean(t));
}
// The volume (4 x 4 x 4): texel (i, j, k) is ((i + 4 j + 16 k) / 64, i / 4, j / 4, k / 4).
Vec4 sample3D(double s, double t, double r) {
    double i = std::floor(4 * s), j = std::floor(4 * t), k = std::floor(4 * r);
    return {(i + 4 * j + 16 * k) / 64, i / 4, j / 4, k / 4};
}
// Cube face k (Vulkan's order +X, -X, +Y, -Y, +Z, -Z) is one solid colour.
Vec4 faceColour(int k) {
    return {(k + 1) / 8.0, 1 - k / 8.0, 0.25 + 0.5 * (k % 2), (k + 2) / 10.0};
}
// The face the shader's TmFaceDirection(u, v) points into.
int faceAt(double u) { return static_cast<int>(std::floor(6 * u)); }
double lit(bool condition) { return condition ? 1.0 : 0.0; }

class HlslTextureMacroTest : public testing::QuadDrawTest {
protected:
    HlslTextureMacroTest() : QuadDrawTest(kSize) {}

    void SetUp() override {
        QuadDrawTest::SetUp();
        if (HasFatalFailure()) return;
        image::Image flat(8, 8, image::PixelFormat::RgbaFloat);
        for (uint32_t y = 0; y < 8; ++y)
            for (uint32_t x = 0; x < 8; ++x) flat.setPixelFloat(x, y, toFloat(texel2D(x, y)));
        auto texture2D = vulkan::Texture::create2D(context(), flat, {false, true, "tm 2D"});
        ASSERT_TRUE(texture2D) << texture2D.error().detail;
        m2D.emplace(std::move(*texture2D));
        std::vector<image::Image> slices;
        for (uint32_t k = 0; k < 4; ++k) {
            image::Image slice(4, 4, image::PixelFormat::RgbaFloat);
            for (uint32_t j = 0; j < 4; ++j)
                for (uint32_t i = 0; i < 4; ++i)
                    slice.setPixelFloat(
                        i, j, toFloat(sample3D((i + 0.5) / 4, (j + 0.5) / 4, (k + 0.5) / 4)));
            slices.push_back(std::move(slice));
        }
        auto volume = vulkan::Texture::createVolume(context(), slices, {false, false, "tm 3D"});
        ASSERT_TRUE(volume) << volume.error().detail;
        m3D.emplace(std::move(*volume));
        std::vector<image::Image> faces;
        for (int k = 0; k < 6; ++k) {
            image::Image face(4, 4, image::PixelFormat::RgbaFloat);
            for (uint32_t y = 0; y < 4; ++y)
                for (uint32_t x = 0; x < 4; ++x) face.setPixelFloat(x, y, toFloat(faceColour(k)));
            faces.push_back(std::move(face));
        }
        auto cube = vulkan::Texture::createCube(context(), faces, {false, false, "tm cube"});
        ASSERT_TRUE(cube) << cube.error().detail;
        mCube.emplace(std::move(*cube));
        vulkan::SamplerDesc nearest;
        nearest.filter = VK_FILTER_NEAREST;
        nearest.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
        nearest.addressMode = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        nearest.name = "tm nearest";
        auto sampler = vulkan::createSampler(context(), nearest);
        ASSERT_TRUE(sampler) << sampler.error().detail;
        mNearest.emplace(std::move(*sampler));
    }
    void TearDown() override {
        mNearest.reset();
        mCube.reset();
        m3D.reset();
        m2D.reset();
        QuadDrawTest::TearDown();
    }
    static std::array<float, 4> toFloat(const Vec4& v) {
        return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]),
                static_cast<float>(v[3])};
    }

    // Draws |keyword| with the test's textures (by dimension; separate samplers get the nearest
    // sampler) and compares 4 channels of every pixel with |formula|.
    void expectFormula(const std::string& keyword, const ShaderValues& values,
                       const Formula& formula, double absolute, double relative) {
        TextureLookup textures = [this](std::string_view name,
                                        pack::ResourceDim dim) -> std::optional<TextureBinding> {
            VkSampler sampler = mNearest->get();
            if (name.starts_with("sampler") || dim == pack::ResourceDim::Dim2D)
                return TextureBinding{m2D->view(), sampler};
            if (dim == pack::ResourceDim::Dim3D) return TextureBinding{m3D->view(), sampler};
            if (dim == pack::ResourceDim::Cube) return TextureBinding{mCube->view(), sampler};
            return std::nullopt;
        };
        expectPassFormula("Test/HlslTextureMacros", keyword, values, textures, formula, 4,
                          absolute, relative, 0.5);
    }

    std::optional<vulkan::Texture> m2D, m3D, mCube;
    std::optional<vulkan::UniqueHandle<VkSampler>> mNearest;
};

// Each declaration macro gives a texture (and sampler_<name> where it declares one) that the
// sampling macros read: plain, with another texture's sampler, and at explicit mip levels.
TEST_F(HlslTextureMacroTest, Texture2D) {
    expectFormula(
        "TM_2D", {},
        [](double u, double v) {
            Vec4 a = sample2D(u, v, 0), b = sample2D(v, u, 0);
            return Vec4{a[0], b[1], a[2] + b[0], a[3] + b[1]};
        },
        1e-3, 0);
    expectFormula(
        "TM_2D_LOD", {},
        [](double u, double v) {
            return Vec4{sample2D(u, v, 1)[0], sample2D(u, v, 2)[1], sample2D(v, u, 0)[0],
                        sample2D(u, v, 3)[3]};
        },
        1e-3, 0);
}

// Depth in .r; shadow-map compares are 1 (lit) where the receiver depth <= the stored depth.
TEST_F(HlslTextureMacroTest, DepthAndShadowMaps) {
    expectFormula(
        "TM_DEPTH", {},
        [](double u, double v) {
            double r = sample2D(u, v, 0)[0], swapped = sample2D(v, u, 0)[0];
            return Vec4{r, swapped, lit(0.51 <= r), lit(0.3 <= swapped)};
        },
        1e-3, 0);
}

// The screen-space texture and shadow mask sample the screen position (projected by w); the
// zero-initialised record sums to the one member set; UNITY_POSITION is the pixel centre.
TEST_F(HlslTextureMacroTest, ScreenSpaceAndOutputs) {
    expectFormula(
        "TM_SCREEN", {},
        [](double u, double v) {
            return Vec4{sample2D(u, v, 0)[1], sample2D(u, v, 0)[0], 1.0, u + 32 * v};
        },
        1e-3, 1e-5);
}

TEST_F(HlslTextureMacroTest, Texture3D) {
    expectFormula(
        "TM_3D", {},
        [](double u, double v) {
            double w = 0.5 * u + 0.2;
            return Vec4{sample3D(u, v, w)[0], sample3D(v, u, w)[1], sample3D(u, v, w)[2],
                        sample3D(w, v, u)[3]};
        },
        1e-3, 0);
}

// Every cube lookup along a direction into face k returns that face's colour.
TEST_F(HlslTextureMacroTest, Cube) {
    expectFormula(
        "TM_CUBE", {}, [](double u, double) { return faceColour(faceAt(u)); }, 1e-3, 0);
    expectFormula(
        "TM_CUBE_ARGS", {},
        [](double u, double) {
            Vec4 c = faceColour(faceAt(u));
            return Vec4{c[0], c[1], c[2] + c[0], c[3]};
        },
        1e-3, 0);
    // texCUBEproj samples along xyz / w; the cube shadow is lit where depth w <= the face's .r.
    expectFormula(
        "TM_CUBE_SHADOW", {},
        [](double u, double v) {
            int k = faceAt(u);
            return Vec4{lit(v <= faceColour(k)[0]), faceColour(k)[1], faceColour(k ^ 1)[2], 0};
        },
        1e-3, 0);
}

// A texture stack samples each layer at the prepared uv (or uv and level); normal layers are
// unpacked as plain RGB (varc defines UNITY_NO_DXT5nm, HLSLSupport.cginc): rgb * 2 - 1 with xy
// times scale. No virtual texturing runtime: the resolve output (feedback) is zero, and with
// UNITY_VIRTUAL_TEXTURING the fallback samples the same texels.
TEST_F(HlslTextureMacroTest, TextureStacks) {
    Formula stack = [](double u, double v) {
        Vec4 a = sample2D(u, v, 0), b = sample2D(v, u, 1);
        return Vec4{a[0], b[1], a[2] * 2 - 1, (b[1] * 2 - 1) * 2.0};
    };
    expectFormula("TM_STACK", {}, stack, 1e-3, 0);
    expectFormula("TM_STACK_VT", {}, stack, 1e-3, 0);
}

// Granite (GraniteShaderLib3.cginc): the per-layer cache accessors read row l of the tile set's
// cache block; the HLSL-family setter returns a modified copy; page translation is uv * t.xy +
// t.zw in layer |layer| with the level-0 page counts (tiles x, tiles x * y scale); debug tiles
// paint red within 2 % of a page edge.
TEST_F(HlslTextureMacroTest, GraniteTileSet) {
    expectFormula(
        "TM_GRANITE", {},
        [](double u, double v) {
            auto frac = [](double x) { return x - std::floor(x); };
            double fx = frac(6.1 * u), fy = frac(3.0 * v);
            bool edge = fx < 0.02 || fx > 0.98 || fy < 0.02 || fy > 0.98;
            double coord = (0.5 * u + 0.25) + 10 * (2 * v - 1) + 100 * 3;
            return Vec4{201 * u + 3010 * v, 1 + 3 * u, coord + 1000 * (4 + 10 * 2),
                        edge ? 1.0 : 5.0};
        },
        1e-4, 2e-6);
}

// Members of blocks declared with each block macro (and a global with DECL_WITH_BINDING) take
// the values set by name.
TEST_F(HlslTextureMacroTest, UniformBlocks) {
    ShaderValues values;
    values.set("_TmA4", glm::vec4(0.5f, 0.25f, 0.0f, 0.0f));
    values.set("_TmB4", glm::vec4(0.0f, 0.0f, 2.0f, 0.0f));
    values.set("_TmC4", glm::vec4(0.0f, 0.0f, 0.0f, -0.5f));
    values.set("_TmD4", glm::vec4(0.125f, 0.0f, 0.0f, 3.0f));
    values.set("_TmE4", glm::vec4(0.0f, 1.0f, 0.75f, 0.0f));
    expectFormula(
        "TM_BLOCKS", values,
        [](double u, double v) {
            return Vec4{0.5 * u + 0.25, 2 * v - 0.5, 0.125 + 3 * u, 1 - 0.75 * v};
        },
        1e-5, 1e-5);
}

}  // namespace
}  // namespace varc::render
