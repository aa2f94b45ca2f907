// SPDX-License-Identifier: Apache-2.0
// PNG encoding/decoding of Images: exact 8-bit round trips, HDR conversion, atomic writes.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include "varc/image/Png.h"

namespace varc::render {
namespace {

using Rgba8 = std::array<uint8_t, 4>;

std::string tempPath(const std::string& name) {
    return ::testing::TempDir() + "varc_png_" + std::to_string(::getpid()) + "_" + name;
}

image::Image randomImage(uint32_t width, uint32_t height) {
    image::Image image(width, height, image::PixelFormat::Rgba8);
    std::mt19937 random(1234);
    for (uint8_t& byte : image.bytes()) byte = static_cast<uint8_t>(random() & 0xFF);
    return image;
}

class PngLevelTest : public ::testing::TestWithParam<int> {};

TEST_P(PngLevelTest, RoundTripsEightBitPixelsExactly) {
    image::Image image = randomImage(37, 23);
    std::string path = tempPath("roundtrip_" + std::to_string(GetParam()) + ".png");
    ASSERT_TRUE(writePng(path, image, GetParam()).ok());
    Result<image::Image> loaded = image::readPng(path);
    ASSERT_TRUE(loaded.ok()) << loaded.error().detail;
    EXPECT_EQ(loaded->width(), 37u);
    EXPECT_EQ(loaded->height(), 23u);
    ASSERT_EQ(loaded->format(), image::PixelFormat::Rgba8);
    EXPECT_TRUE(std::equal(image.bytes().begin(), image.bytes().end(), loaded->bytes().begin()));
    std::filesystem::remove(path);
}

INSTANTIATE_TEST_SUITE_P(ZlibLevels, PngLevelTest, ::testing::Values(0, 1, 6, 9));

TEST(Png, HdrImagesAreClampedToEightBits) {
    image::Image hdr(2, 1, image::PixelFormat::RgbaFloat);
    hdr.setPixelFloat(0, 0, {-1.0f, 0.5f, 2.0f, 0.25f});
    hdr.setPixelFloat(1, 0, {1.0f, 0.0f, 1000.0f, 7.0f});
    Result<std::string> encoded = encodePng(hdr);
    ASSERT_TRUE(encoded.ok()) << encoded.error().detail;
    Result<image::Image> decoded = image::decodePng(*encoded);
    ASSERT_TRUE(decoded.ok()) << decoded.error().detail;
    EXPECT_EQ(decoded->pixel8(0, 0), (Rgba8{0, 128, 255, 64}));
    EXPECT_EQ(decoded->pixel8(1, 0), (Rgba8{255, 0, 255, 255}));
}

TEST(Png, ReinhardTonemapCompressesColourButNotAlpha) {
    image::Image hdr(1, 1, image::PixelFormat::RgbaFloat);
    hdr.setPixelFloat(0, 0, {1.0f, 3.0f, -1.0f, 0.5f});
    // 1 / 2 = 0.5 -> 128; 3 / 4 = 0.75 -> 191; negative -> 0; alpha only clamped.
    EXPECT_EQ(hdr.toRgba8(image::Tonemap::Reinhard).pixel8(0, 0), (Rgba8{128, 191, 0, 128}));
}

TEST(Png, OverwritesAtomicallyWithoutLeavingTemporaries) {
    std::filesystem::path dir = tempPath("atomic_dir");
    std::filesystem::create_directories(dir);
    std::string path = (dir / "out.png").string();
    ASSERT_TRUE(writePng(path, randomImage(8, 8)).ok());
    image::Image second(4, 4, image::PixelFormat::Rgba8);
    ASSERT_TRUE(writePng(path, second).ok());
    Result<image::Image> loaded = image::readPng(path);
    ASSERT_TRUE(loaded.ok());
    EXPECT_EQ(loaded->width(), 4u);
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir),
                            std::filesystem::directory_iterator()),
              1);
    std::filesystem::remove_all(dir);
}

TEST(Png, ErrorsAreResults) {
    Result<image::Image> missing = image::readPng(tempPath("does_not_exist.png"));
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().code, ErrorCode::IoError);

    Result<std::string> encoded = encodePng(randomImage(16, 16));
    ASSERT_TRUE(encoded.ok());
    Result<image::Image> truncated =
        image::decodePng(std::string_view(*encoded).substr(0, encoded->size() / 2));
    ASSERT_FALSE(truncated.ok());
    EXPECT_EQ(truncated.error().code, ErrorCode::InvalidInput);
    Result<image::Image> garbage = image::decodePng("definitely not a png");
    ASSERT_FALSE(garbage.ok());
    EXPECT_EQ(garbage.error().code, ErrorCode::InvalidInput);

    EXPECT_EQ(encodePng(image::Image()).error().code, ErrorCode::InvalidInput);
    EXPECT_EQ(encodePng(randomImage(2, 2), 10).error().code, ErrorCode::InvalidInput);
    Status unwritable = writePng("/nonexistent-dir/varc.png", randomImage(2, 2));
    ASSERT_FALSE(unwritable.ok());
    EXPECT_EQ(unwritable.error().code, ErrorCode::IoError);
}

// A PNG whose IHDR promises |width| x |height| RGBA8 pixels and whose one IDAT holds five zero
// bytes (a stored zlib block): a header that promises pixels the file does not hold.
std::string truncatedPng(uint32_t width, uint32_t height) {
    auto crc32 = [](std::string_view bytes) {
        uint32_t crc = 0xFFFFFFFFu;
        for (unsigned char byte : bytes) {
            crc ^= byte;
            for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
        }
        return ~crc;
    };
    auto bigEndian = [](uint32_t value) {
        return std::string{static_cast<char>(value >> 24), static_cast<char>(value >> 16),
                           static_cast<char>(value >> 8), static_cast<char>(value)};
    };
    auto chunk = [&](const std::string& type, const std::string& data) {
        return bigEndian(static_cast<uint32_t>(data.size())) + type + data +
               bigEndian(crc32(type + data));
    };
    std::string header = bigEndian(width) + bigEndian(height) + std::string("\x08\x06\0\0\0", 5);
    std::string fiveZeros("\x78\x01\x01\x05\x00\xfa\xff\0\0\0\0\0\x00\x05\x00\x01", 16);
    return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", header) +
           chunk("IDAT", fiveZeros) + chunk("IEND", "");
}

// kMaxPngPixels (docs/SECURITY.md): a header of exactly the limit gets as far as reading pixels
// (and fails there, for want of them); one row more is refused from the header alone.
TEST(Png, AHeaderAtThePixelLimitIsReadAndOnePastIsRefused) {
    static_assert(uint64_t{16384} * 16384 == image::kMaxPngPixels);
    Result<image::Image> atTheLimit = image::decodePng(truncatedPng(16384, 16384));
    ASSERT_FALSE(atTheLimit.ok());
    EXPECT_EQ(atTheLimit.error().detail.find("too large"), std::string::npos)
        << atTheLimit.error().detail;
    EXPECT_NE(atTheLimit.error().detail.find("corrupt PNG"), std::string::npos)
        << atTheLimit.error().detail;
    Result<image::Image> past = image::decodePng(truncatedPng(16384, 16385));
    ASSERT_FALSE(past.ok());
    EXPECT_NE(past.error().detail.find("too large"), std::string::npos) << past.error().detail;
    EXPECT_EQ(image::decodePng(truncatedPng(2, 2)).error().detail.find("too large"),
              std::string::npos);
}

TEST(HalfFloat, ConvertsSpecialValues) {
    EXPECT_EQ(image::halfToFloat(0x3C00), 1.0f);
    EXPECT_EQ(image::halfToFloat(0xC000), -2.0f);
    EXPECT_EQ(image::halfToFloat(0x7BFF), 65504.0f);
    EXPECT_EQ(image::halfToFloat(0x0001), std::ldexp(1.0f, -24));
    EXPECT_TRUE(std::isinf(image::halfToFloat(0x7C00)));
    EXPECT_TRUE(std::isnan(image::halfToFloat(0x7E00)));
    EXPECT_TRUE(std::signbit(image::halfToFloat(0x8000)));
    EXPECT_EQ(image::floatToHalf(65519.0f), 0x7BFF);
    EXPECT_EQ(image::floatToHalf(65520.0f), 0x7C00);
    EXPECT_EQ(image::floatToHalf(1.0f + std::ldexp(1.0f, -11)), 0x3C00);  // tie rounds to even
}

TEST(HalfFloat, EveryNonNanHalfRoundTrips) {
    for (uint32_t bits = 0; bits <= 0xFFFF; ++bits) {
        auto half = static_cast<uint16_t>(bits);
        float value = image::halfToFloat(half);
        if (std::isnan(value)) continue;
        ASSERT_EQ(image::floatToHalf(value), half) << "0x" << std::hex << bits;
    }
}

}  // namespace
}  // namespace varc::render
