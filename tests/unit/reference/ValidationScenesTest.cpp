// SPDX-License-Identifier: Apache-2.0
// Renders every shipped forward validation scene (tests/scenes/forward/*.json) with the CPU
// reference: no error, no NaN, lit pixels; writes <scene>.png and <scene>.classes.png to
// $VARC_REFERENCE_OUT (default: a temporary directory) so that a person can look at them.
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include <gtest/gtest.h>

#include "varc/image/Png.h"
#include "varc/reference/ReferenceRenderer.h"
#include "varc/scene/Scene.h"

namespace varc::reference {
namespace {

namespace fs = std::filesystem;

fs::path outputDir() {
    const char* env = std::getenv("VARC_REFERENCE_OUT");
    fs::path dir = env != nullptr ? fs::path(env) : fs::path(::testing::TempDir()) / "varc-reference";
    fs::create_directories(dir);
    return dir;
}

image::Image classImage(const Classification& c) {
    image::Image image(c.width, c.height, image::PixelFormat::Rgba8);
    for (uint32_t y = 0; y < c.height; ++y) {
        for (uint32_t x = 0; x < c.width; ++x) {
            const uint8_t v = c.at(x, y) == PixelClass::Interior ? 255 : c.at(x, y) == PixelClass::Edge ? 128 : 0;
            image.setPixel8(x, y, {v, v, v, 255});
        }
    }
    return image;
}

TEST(ValidationScenes, EveryForwardSceneRenders) {
    const fs::path dir = fs::path(VARC_SOURCE_DIR) / "tests/scenes/forward";
    const fs::path out = outputDir();
    int scenes = 0;
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.path().extension() != ".json") continue;
        ++scenes;
        const std::string name = entry.path().stem().string();
        auto scene = scene::loadScene(entry.path().string());
        ASSERT_TRUE(scene.ok()) << scene.error().detail;
        auto image = renderReference(*scene);
        ASSERT_TRUE(image.ok()) << name << ": " << image.error().detail;
        size_t interior = 0, lit = 0;
        for (uint32_t y = 0; y < image->color.height(); ++y) {
            for (uint32_t x = 0; x < image->color.width(); ++x) {
                const auto p = image->color.pixelFloat(x, y);
                for (float v : p) ASSERT_TRUE(std::isfinite(v)) << name << " " << x << "," << y;
                if (image->classes.at(x, y) == PixelClass::Interior) {
                    ++interior;
                    lit += p[0] + p[1] + p[2] > 0.3f ? 1 : 0;
                }
            }
        }
        EXPECT_GT(interior, image->color.width() * image->color.height() / 5) << name;
        EXPECT_GT(lit, interior / 10) << name;
        ASSERT_TRUE(image::writePng((out / (name + ".png")).string(), image->color).ok());
        ASSERT_TRUE(
            image::writePng((out / (name + ".classes.png")).string(), classImage(image->classes))
                .ok());
    }
    EXPECT_GE(scenes, 8);
    std::printf("reference images in %s\n", out.string().c_str());
}

}  // namespace
}  // namespace varc::reference
