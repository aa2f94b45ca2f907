// SPDX-License-Identifier: Apache-2.0
// Image: RGBA pixels in host memory, 8-bit or 32-bit float, as read back or loaded from PNG.
#include "varc/image/Image.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "varc/core/Check.h"

namespace varc::image {

namespace {

uint8_t toByte(float value, Tonemap tonemap) {
    if (std::isnan(value)) return 0;
    if (tonemap == Tonemap::Reinhard) value = value > 0.0f ? value / (1.0f + value) : 0.0f;
    float clamped = std::clamp(value, 0.0f, 1.0f);
    return static_cast<uint8_t>(std::lround(clamped * 255.0f));
}

}  // namespace

Image::Image(uint32_t width, uint32_t height, PixelFormat format)
    : mWidth(width), mHeight(height), mFormat(format) {
    std::size_t values = std::size_t{width} * height * 4;
    if (isFloat()) {
        mFloats.assign(values, 0.0f);
    } else {
        mBytes.assign(values, 0);
    }
}

std::span<uint8_t> Image::bytes() {
    VARC_CHECK(!isFloat()) << "Image::bytes() on a float image";
    return mBytes;
}
std::span<const uint8_t> Image::bytes() const {
    VARC_CHECK(!isFloat()) << "Image::bytes() on a float image";
    return mBytes;
}
std::span<float> Image::floats() {
    VARC_CHECK(isFloat()) << "Image::floats() on an 8-bit image";
    return mFloats;
}
std::span<const float> Image::floats() const {
    VARC_CHECK(isFloat()) << "Image::floats() on an 8-bit image";
    return mFloats;
}

std::size_t Image::offset(uint32_t x, uint32_t y) const {
    VARC_CHECK(x < mWidth && y < mHeight)
        << "pixel (" << x << ", " << y << ") outside " << mWidth << "x" << mHeight;
    return (std::size_t{y} * mWidth + x) * 4;
}

std::array<uint8_t, 4> Image::pixel8(uint32_t x, uint32_t y) const {
    std::span<const uint8_t> p = bytes().subspan(offset(x, y), 4);
    return {p[0], p[1], p[2], p[3]};
}

std::array<float, 4> Image::pixelFloat(uint32_t x, uint32_t y) const {
    std::size_t at = offset(x, y);
    if (isFloat()) return {mFloats[at], mFloats[at + 1], mFloats[at + 2], mFloats[at + 3]};
    return {mBytes[at] / 255.0f, mBytes[at + 1] / 255.0f, mBytes[at + 2] / 255.0f,
            mBytes[at + 3] / 255.0f};
}

void Image::setPixel8(uint32_t x, uint32_t y, const std::array<uint8_t, 4>& rgba) {
    std::copy(rgba.begin(), rgba.end(), bytes().subspan(offset(x, y), 4).begin());
}

void Image::setPixelFloat(uint32_t x, uint32_t y, const std::array<float, 4>& rgba) {
    std::copy(rgba.begin(), rgba.end(), floats().subspan(offset(x, y), 4).begin());
}

Image Image::toRgba8(Tonemap tonemap) const {
    if (!isFloat()) return *this;
    Image out(mWidth, mHeight, PixelFormat::Rgba8);
    for (std::size_t i = 0; i < mFloats.size(); ++i) {
        // Alpha (every fourth value) is never tonemapped, only clamped.
        out.mBytes[i] = toByte(mFloats[i], i % 4 == 3 ? Tonemap::Clamp : tonemap);
    }
    return out;
}

// binary16: 1 sign bit, 5 exponent bits (bias 15), 10 mantissa bits.
float halfToFloat(uint16_t half) {
    uint32_t sign = uint32_t{half & 0x8000u} << 16;
    uint32_t exponent = (half >> 10) & 0x1Fu;
    uint32_t mantissa = half & 0x3FFu;
    if (exponent == 0x1F) return std::bit_cast<float>(sign | 0x7F800000u | (mantissa << 13));
    if (exponent == 0) {
        // Zero or subnormal: mantissa * 2^-24, exact in binary32.
        float magnitude = std::ldexp(static_cast<float>(mantissa), -24);
        return sign ? -magnitude : magnitude;
    }
    return std::bit_cast<float>(sign | ((exponent + 112u) << 23) | (mantissa << 13));
}

uint16_t floatToHalf(float value) {
    uint32_t bits = std::bit_cast<uint32_t>(value);
    auto sign = static_cast<uint16_t>((bits >> 16) & 0x8000u);
    uint32_t magnitude = bits & 0x7FFFFFFFu;
    if (magnitude > 0x7F800000u) return static_cast<uint16_t>(sign | 0x7E00u);   // NaN
    if (magnitude >= 0x477FF000u) return static_cast<uint16_t>(sign | 0x7C00u);  // >= 65520: inf
    if (magnitude < 0x38800000u) {
        // Below the smallest normal half (2^-14): a subnormal, rounded to nearest even.
        float scaled = std::ldexp(std::bit_cast<float>(magnitude), 24);
        return static_cast<uint16_t>(sign | static_cast<uint16_t>(std::nearbyint(scaled)));
    }
    // Normal: rebias the exponent, round the 13 dropped mantissa bits to nearest even.
    uint32_t rebased = magnitude - (112u << 23);
    uint32_t rounded = rebased + 0xFFFu + ((rebased >> 13) & 1u);
    return static_cast<uint16_t>(sign | (rounded >> 13));
}

}  // namespace varc::image
