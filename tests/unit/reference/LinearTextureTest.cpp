// SPDX-License-Identifier: Apache-2.0
// LinearTexture: sRGB decoded per texel, then bilinear with repeat, as the GPU samples it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>

#include "varc/image/Png.h"
#include "varc/reference/LinearTexture.h"

namespace varc::reference {
namespace {

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

TEST(LinearTexture, DecodesSrgbThenFiltersBilinearlyWithRepeat) {
    image::Image image(2, 1, image::PixelFormat::Rgba8);
    image.setPixel8(0, 0, {0, 64, 255, 255});
    image.setPixel8(1, 0, {255, 192, 0, 51});
    const std::string path = (std::filesystem::path(::testing::TempDir()) /
                              ("varc-linear-texture-" + std::to_string(::getpid()) + ".png"))
                                 .string();
    ASSERT_TRUE(image::writePng(path, image).ok());
    auto texture = LinearTexture::load(path);
    std::filesystem::remove(path);
    ASSERT_TRUE(texture.ok()) << texture.error().detail;
    const LinearTexture& t = **texture;
    // Texel centres give the decoded texels; alpha stays linear.
    glm::vec4 left = t.sample({0.25f, 0.5f});
    EXPECT_FLOAT_EQ(left.g, srgbToLinear(64.0f / 255.0f));
    EXPECT_FLOAT_EQ(left.b, 1.0f);
    EXPECT_FLOAT_EQ(t.sample({0.75f, 0.5f}).a, 0.2f);
    // Halfway between the centres: the mean of the linear values, not of the sRGB bytes.
    glm::vec4 middle = t.sample({0.5f, 0.5f});
    EXPECT_NEAR(middle.g, 0.5f * (srgbToLinear(64.0f / 255.0f) + srgbToLinear(192.0f / 255.0f)),
                1e-6f);
    // Repeat: u = 0 lies halfway between the last and the first texel.
    EXPECT_NEAR(t.sample({0.0f, 0.5f}).r, 0.5f, 1e-6f);
    EXPECT_NEAR(t.sample({1.25f, 0.5f}).g, left.g, 1e-6f);
}

TEST(LinearTexture, AMissingFileIsAnErrorNamingIt) {
    auto texture = LinearTexture::load("/nonexistent/varc.png");
    ASSERT_FALSE(texture.ok());
    EXPECT_NE(texture.error().detail.find("/nonexistent/varc.png"), std::string::npos);
}

}  // namespace
}  // namespace varc::reference
