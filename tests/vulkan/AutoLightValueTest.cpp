// SPDX-License-Identifier: Apache-2.0
// Value tests of AutoLight.cginc's light attenuation (issue #27, docs/BUILTIN_API.md): each light
// type of tests/vulkan/helpers/AutoLightValues.shader runs on lavapipe with two 4 x 4 textures
// of known texels bound as _LightTexture0 and _LightTextureB0 (nearest filtering) and is
// compared with the attenuation Unity documents for forward-add lights: a point light reads its
// falloff texture at dot(lc, lc) (red channel), a spot light multiplies (lc.z > 0), the cookie's
// alpha at lc.xy / lc.w + 0.5 and the falloff at dot(lc.xyz, lc.xyz); a point light with a
// cookie multiplies the falloff by the cube cookie's alpha (a white cube here); a directional
// light is unattenuated, a directional cookie is the cookie's alpha at lc.xy. No shadows, so
// SHADOW_ATTENUATION is 1. scripts/builtin-api.py counts the names on the api-value-tested lines
// below as implemented.
//
// api-value-tested: UnitySpotCookie UnitySpotAttenuate LIGHTING_COORDS DECLARE_LIGHT_COORDS
// api-value-tested: TRANSFER_VERTEX_TO_FRAGMENT COMPUTE_LIGHT_COORDS LIGHT_ATTENUATION
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <glm/glm.hpp>
#include <string>

#include "FormulaComparison.h"
#include "QuadDrawTest.h"
#include "varc/vulkan/Sampler.h"
#include "varc/vulkan/Texture.h"

namespace varc::render {
namespace {

constexpr uint32_t kSize = 32;
using Vec4 = std::array<double, 4>;
using Texel = std::array<uint8_t, 4>;
using TexelRule = std::function<Texel(uint32_t x, uint32_t y)>;

// _LightTexture0 (cookie, or the point light's falloff) and _LightTextureB0 (spot falloff).
Texel cookieTexel(uint32_t x, uint32_t y) {
    return {static_cast<uint8_t>(10 + 60 * x), static_cast<uint8_t>(20 + 60 * y),
            static_cast<uint8_t>(5 + 25 * (x + y)), static_cast<uint8_t>(255 - 40 * x - 10 * y)};
}
Texel falloffTexel(uint32_t x, uint32_t y) {
    return {static_cast<uint8_t>(200 - 45 * x - 5 * y), 0, 0, 255};
}
double channel(const TexelRule& rule, uint32_t x, uint32_t y, int c) {
    return rule(x, y)[c] / 255.0;
}

class AutoLightValueTest : public testing::QuadDrawTest {
protected:
    AutoLightValueTest() : QuadDrawTest(kSize) {}

    void SetUp() override {
        QuadDrawTest::SetUp();
        if (HasFatalFailure()) return;
        mCookie = makeTexture(cookieTexel);
        mFalloff = makeTexture(falloffTexel);
        vulkan::SamplerDesc nearest;
        nearest.filter = VK_FILTER_NEAREST;
        nearest.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
        nearest.addressMode = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
        auto sampler = vulkan::createSampler(context(), nearest);
        ASSERT_TRUE(sampler) << sampler.error().detail;
        mSampler = std::move(*sampler);
    }
    void TearDown() override {
        mCookie.reset();
        mFalloff.reset();
        mSampler.reset();
        QuadDrawTest::TearDown();
    }

    std::optional<vulkan::Texture> makeTexture(const TexelRule& rule) {
        image::Image image(4, 4, image::PixelFormat::Rgba8);
        for (uint32_t y = 0; y < 4; ++y)
            for (uint32_t x = 0; x < 4; ++x) image.setPixel8(x, y, rule(x, y));
        auto texture = vulkan::Texture::create2D(context(), image);
        EXPECT_TRUE(texture) << texture.error().detail;
        if (!texture) return std::nullopt;
        return std::move(*texture);
    }

    // Draws the light type |keyword|; |formula| gets the texel column and row (i, j) of the
    // pixel and the pixel's v.
    void expectFormula(const std::string& keyword, int channels,
                       const std::function<Vec4(uint32_t i, uint32_t j, double v)>& formula) {
        ASSERT_TRUE(mCookie && mFalloff);
        reader::PassView pass = *mPack->findShader("Test/AutoLightValues")->pass(0);
        TextureLookup textures = [this](std::string_view name,
                                        pack::ResourceDim dim) -> std::optional<TextureBinding> {
            if (dim != pack::ResourceDim::Dim2D) return mTextures->named("white", dim);
            const vulkan::Texture& texture = name == "_LightTextureB0" ? *mFalloff : *mCookie;
            return TextureBinding{texture.view(), mSampler.get()};
        };
        ShaderValues values;
        values.set("unity_ObjectToWorld", glm::mat4(1.0f));
        values.set("unity_WorldToLight", glm::mat4(1.0f));
        image::Image image = drawQuad(pass, {keyword}, values, textures);
        ASSERT_EQ(image.width(), kSize) << keyword;
        testing::FormulaComparison result = testing::compareWithFormula(
            image,
            [&formula](double u, double v) {
                return formula(static_cast<uint32_t>(u * 4), static_cast<uint32_t>(v * 4), v);
            },
            channels, 1e-5, 1e-4);
        EXPECT_LE(result.worst, 1.0) << keyword << ": worst " << result.where;
        EXPECT_GT(result.largest, 0.1) << keyword;
    }

    std::optional<vulkan::Texture> mCookie, mFalloff;
    vulkan::UniqueHandle<VkSampler> mSampler;
};

// The falloff lookup at dot(lc, lc) = the centre of column i (row i too: .rr).
TEST_F(AutoLightValueTest, PointLight) {
    expectFormula("POINT", 1, [](uint32_t i, uint32_t, double) {
        return Vec4{channel(cookieTexel, i, i, 0), 0, 0, 0};
    });
    expectFormula("POINT_COOKIE", 1, [](uint32_t i, uint32_t, double) {
        return Vec4{channel(falloffTexel, i, i, 0) * 1.0, 0, 0, 0};
    });
}

// Cookie alpha at texel (i, j), falloff red at texel (1, 1) (dot = 0.375), zero behind the light.
TEST_F(AutoLightValueTest, SpotLight) {
    expectFormula("SPOT", 4, [](uint32_t i, uint32_t j, double v) {
        double cookie = channel(cookieTexel, i, j, 3), falloff = channel(falloffTexel, 1, 1, 0);
        double x = (i + 0.5) / 4 - 0.5, y = (j + 0.5) / 4 - 0.5;
        double z = std::sqrt(0.375 - x * x - y * y) * (v > 0.75 ? -1.0 : 1.0);
        return Vec4{z > 0 ? cookie * falloff : 0.0, cookie, falloff, z};
    });
}

TEST_F(AutoLightValueTest, DirectionalLight) {
    expectFormula("DIRECTIONAL", 1, [](uint32_t, uint32_t, double) { return Vec4{1, 0, 0, 0}; });
    expectFormula("DIRECTIONAL_COOKIE", 1, [](uint32_t i, uint32_t j, double) {
        return Vec4{channel(cookieTexel, i, j, 3), 0, 0, 0};
    });
}

}  // namespace
}  // namespace varc::render
