// SPDX-License-Identifier: Apache-2.0
// Image: RGBA pixels in host memory, 8-bit or 32-bit float, as read back or loaded from PNG.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace varc::image {

enum class PixelFormat {
    Rgba8,      // 4 bytes per pixel, as stored (sRGB-encoded when the source was an sRGB format)
    RgbaFloat,  // 4 floats per pixel, linear, unclamped (HDR)
};

// How a float image becomes 8-bit (Image::toRgba8, writePng). Neither applies sRGB encoding.
enum class Tonemap {
    Clamp,     // round(clamp(v, 0, 1) * 255) per channel
    Reinhard,  // colour channels v / (1 + v) first (v < 0 clamps to 0); alpha is clamped
};

// Rows top to bottom, pixels left to right, channels R, G, B, A. Coordinates out of range are
// programmer errors (VARC_CHECK).
class Image {
public:
    Image() = default;
    // A zero-filled image of |width| x |height| pixels.
    Image(uint32_t width, uint32_t height, PixelFormat format);

    uint32_t width() const { return mWidth; }
    uint32_t height() const { return mHeight; }
    PixelFormat format() const { return mFormat; }
    bool isFloat() const { return mFormat == PixelFormat::RgbaFloat; }

    // The pixel storage; bytes() needs Rgba8, floats() needs RgbaFloat.
    std::span<uint8_t> bytes();
    std::span<const uint8_t> bytes() const;
    std::span<float> floats();
    std::span<const float> floats() const;

    // The pixel at (|x|, |y|) of an Rgba8 image.
    std::array<uint8_t, 4> pixel8(uint32_t x, uint32_t y) const;
    // The pixel at (|x|, |y|) as floats: raw for RgbaFloat, value / 255 for Rgba8.
    std::array<float, 4> pixelFloat(uint32_t x, uint32_t y) const;
    void setPixel8(uint32_t x, uint32_t y, const std::array<uint8_t, 4>& rgba);
    void setPixelFloat(uint32_t x, uint32_t y, const std::array<float, 4>& rgba);

    // An Rgba8 copy: unchanged for Rgba8 images, converted with |tonemap| for float ones.
    Image toRgba8(Tonemap tonemap = Tonemap::Clamp) const;

private:
    std::size_t offset(uint32_t x, uint32_t y) const;

    uint32_t mWidth = 0;
    uint32_t mHeight = 0;
    PixelFormat mFormat = PixelFormat::Rgba8;
    std::vector<uint8_t> mBytes;
    std::vector<float> mFloats;
};

// IEEE 754 binary16 <-> binary32. halfToFloat is exact (subnormals, infinities and NaN kept);
// floatToHalf rounds to nearest even and saturates to infinity.
float halfToFloat(uint16_t half);
uint16_t floatToHalf(float value);

}  // namespace varc::image
