// SPDX-License-Identifier: Apache-2.0
// ImageRelations on synthetic images: sums, tolerances, saturation, the 3x3 window, NaN.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "varc/properties/ImageRelations.h"

namespace varc::properties {
namespace {

using image::Image;
using image::PixelFormat;

Image filled(float value, uint32_t size = 8) {
    Image image(size, size, PixelFormat::RgbaFloat);
    for (size_t i = 0; i < image.floats().size(); ++i) image.floats()[i] = i % 4 == 3 ? 1 : value;
    return image;
}

Image filled8(uint8_t value, uint32_t size = 8) {
    Image image(size, size, PixelFormat::Rgba8);
    for (size_t i = 0; i < image.bytes().size(); ++i) image.bytes()[i] = i % 4 == 3 ? 255 : value;
    return image;
}

TEST(ImageRelationsTest, ASumOfRendersMatchesItsRender) {
    Image a = filled(0.25f), b = filled(0.5f), none = filled(0.125f), both = filled(0.625f);
    RelationCheck check = checkRelation(both, {{&a, 1}, {&b, 1}, {&none, -1}}, {});
    EXPECT_TRUE(check.passed) << check.summary();
    EXPECT_EQ(check.comparedPixels, 64u);
    EXPECT_FLOAT_EQ(check.expected.pixelFloat(3, 3)[1], 0.625f);
}

TEST(ImageRelationsTest, OnePixelOffFailsAndIsReportedFirst) {
    Image a = filled(0.25f), actual = filled(0.5f);
    actual.setPixelFloat(5, 2, {0.5f, 0.9f, 0.5f, 1.0f});
    RelationCheck check = checkRelation(actual, {{&a, 2}}, {0.01f, 0, 0});
    ASSERT_FALSE(check.passed);
    EXPECT_EQ(check.failingPixels, 1u);
    ASSERT_EQ(check.worst.size(), 1u);
    EXPECT_EQ(check.worst[0].x, 5u);
    EXPECT_EQ(check.worst[0].y, 2u);
    EXPECT_EQ(check.worst[0].channel, 1);
    EXPECT_FLOAT_EQ(check.worst[0].expected, 0.5f);
    EXPECT_FLOAT_EQ(check.worst[0].actual, 0.9f);
    EXPECT_NE(check.summary().find("(5,2) G expected 0.5 got 0.9"), std::string::npos)
        << check.summary();
    EXPECT_EQ(check.diff.pixel8(5, 2), (std::array<uint8_t, 4>{255, 0, 0, 255}));
}

TEST(ImageRelationsTest, RelativeToleranceScalesWithTheTerms) {
    Image a = filled(100.0f), actual = filled(100.04f);
    EXPECT_TRUE(checkRelation(actual, {{&a, 1}}, {0, 1.0f / 2048.0f, 0}).passed);
    EXPECT_FALSE(checkRelation(actual, {{&a, 1}}, {0, 1.0f / 4096.0f, 0}).passed);
}

TEST(ImageRelationsTest, SaturatedPixelsAreNotCompared) {
    Image a = filled8(200), b = filled8(100), none = filled8(0), both = filled8(255);
    Tolerance ldr{2.0f / 255.0f, 0, 0, 254.0f / 255.0f};
    RelationCheck clamped = checkRelation(both, {{&a, 1}, {&b, 1}, {&none, -1}}, ldr);
    EXPECT_TRUE(clamped.passed);
    EXPECT_EQ(clamped.comparedPixels, 0u);
    Image c = filled8(50), sum = filled8(152);  // 100 + 50 = 150, two LSB off: allowed
    EXPECT_TRUE(checkRelation(sum, {{&b, 1}, {&c, 1}, {&none, -1}}, ldr).passed);
    Image far = filled8(153);  // three LSB: not allowed
    EXPECT_FALSE(checkRelation(far, {{&b, 1}, {&c, 1}, {&none, -1}}, ldr).passed);
}

TEST(ImageRelationsTest, TheWindowForgivesAnEdgeMovedByOnePixel) {
    Image a = filled(0.0f, 8), b = filled(0.0f, 8);
    for (uint32_t y = 0; y < 8; ++y) {
        for (uint32_t x = 0; x < 8; ++x) {
            if (x >= 4) a.setPixelFloat(x, y, {1, 1, 1, 1});
            if (x >= 5) b.setPixelFloat(x, y, {1, 1, 1, 1});
        }
    }
    EXPECT_FALSE(checkRelation(b, {{&a, 1}}, {0.001f, 0, 0}).passed);
    EXPECT_TRUE(checkRelation(b, {{&a, 1}}, {0.001f, 0, 1}).passed);
    Image c = filled(0.0f, 8);  // moved by two pixels: still a failure
    for (uint32_t y = 0; y < 8; ++y)
        for (uint32_t x = 6; x < 8; ++x) c.setPixelFloat(x, y, {1, 1, 1, 1});
    EXPECT_FALSE(checkRelation(c, {{&a, 1}}, {0.001f, 0, 1}).passed);
}

TEST(ImageRelationsTest, TheWindowWorksBothWays) {
    // A bright pixel only in the actual image: every expected neighbour is dark, so it fails
    // even though the expected pixel itself has dark neighbours in the actual image.
    Image expected = filled(0.0f), actual = filled(0.0f);
    actual.setPixelFloat(3, 3, {1, 1, 1, 1});
    EXPECT_FALSE(checkRelation(actual, {{&expected, 1}}, {0.001f, 0, 1}).passed);
}

TEST(ImageRelationsTest, QuarterTurnMovesEachPixelClockwise) {
    Image image = filled(0.0f, 4);
    image.setPixelFloat(1, 0, {0.5f, 0.0f, 0.0f, 1.0f});  // top row, second column
    Image bytes = filled8(0, 4);
    bytes.setPixel8(1, 0, {7, 0, 0, 255});
    Image turned = quarterTurned(image), turned8 = quarterTurned(bytes);
    // (x, y) -> (size - 1 - y, x): the top row becomes the right column.
    EXPECT_FLOAT_EQ(turned.pixelFloat(3, 1)[0], 0.5f);
    EXPECT_FLOAT_EQ(turned.pixelFloat(1, 0)[0], 0.0f);
    EXPECT_EQ(turned8.bytes()[(1 * 4 + 3) * 4], 7);
    Image full = quarterTurned(quarterTurned(quarterTurned(quarterTurned(image))));
    EXPECT_TRUE(std::equal(full.floats().begin(), full.floats().end(), image.floats().begin()));
}

TEST(ImageRelationsTest, NanFailsItsPixelAndIsFound) {
    Image a = filled(0.5f), actual = filled(0.5f);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    actual.setPixelFloat(1, 6, {nan, 0.5f, 0.5f, 1.0f});
    actual.setPixelFloat(2, 6, {0.5f, 0.5f, std::numeric_limits<float>::infinity(), 1.0f});
    RelationCheck check = checkRelation(actual, {{&a, 1}}, {1.0f, 0, 1});
    EXPECT_FALSE(check.passed);
    EXPECT_EQ(check.failingPixels, 2u);
    NonFinite found = findNonFinite(actual);
    EXPECT_EQ(found.count, 2u);
    EXPECT_EQ(found.firstX, 1u);
    EXPECT_EQ(found.firstY, 6u);
    EXPECT_EQ(findNonFinite(a).count, 0u);
    EXPECT_EQ(findNonFinite(filled8(7)).count, 0u);
}

TEST(ImageRelationsTest, PixelsBrighterCountsLitPixels) {
    Image dark = filled(0.0f), lit = filled(0.0f);
    lit.setPixelFloat(0, 0, {0.0f, 0.5f, 0.0f, 1.0f});
    lit.setPixelFloat(1, 0, {0.01f, 0.0f, 0.0f, 1.0f});
    EXPECT_EQ(pixelsBrighter(lit, dark, 1.0f / 64.0f), 1u);
    EXPECT_EQ(pixelsBrighter(dark, lit, 1.0f / 64.0f), 0u);
}

}  // namespace
}  // namespace varc::properties
