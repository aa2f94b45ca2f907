// SPDX-License-Identifier: Apache-2.0
// ImageCompare: compares a GPU render with the CPU reference under the tolerances of
// docs/LIGHTING.md §9.2 and draws a diff image.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "varc/image/Image.h"
#include "varc/reference/Rasterizer.h"

namespace varc::reference {

// Errors are in LSB of 8-bit colour (1 LSB = 1/255), per channel.
struct Tolerance {
    float interiorLsb = 1.0f;   // interior and background pixels; 2-3 for variants with
                                // transcendental functions or filtered textures
    float edgeLsb = 1.0f;       // edge pixels, against the reference at the pixel or a neighbour
    float meanLsb = 0.25f;      // |mean signed error| over interior pixels and channels
    bool compareAlpha = false;  // alpha is not displayed; blend setups may differ in it
    uint32_t maxReported = 10;  // failing pixels listed in CompareResult::firstFailures
};

struct PixelFailure {
    uint32_t x = 0, y = 0;
    PixelClass pixelClass = PixelClass::Interior;
    std::array<float, 4> rendered{}, reference{};  // 0..1
    float errorLsb = 0.0f;  // largest channel error (best neighbour for edges)
};

struct CompareResult {
    bool passed = false;
    float maxErrorLsb = 0.0f;         // over all pixels (edges: best match in the neighbourhood)
    float meanSignedErrorLsb = 0.0f;  // interior pixels, all compared channels
    float meanAbsErrorLsb = 0.0f;     // interior pixels, all compared channels
    uint64_t failingPixels = 0;
    uint64_t interiorPixels = 0, edgePixels = 0, backgroundPixels = 0;
    uint64_t intervalPixels = 0;  // interior pixels whose reference is an interval (shadow edges)
    std::vector<PixelFailure> firstFailures;  // row-major order
    std::string message;  // one line: pass/fail, max/mean error, failing count, first failure
    // Rgba8, same size: grey = the reference's luminance / 4; red = too bright, blue = too dark
    // (32 levels per LSB); failing pixels fully saturated, with green 255.
    image::Image diff;
    // Rgba8, same size: what each pixel was checked as. kMaskBackground (dark grey), kMaskInterior
    // (mid grey), kMaskEdge (yellow: matched against its neighbourhood), kMaskInterval (cyan:
    // interior pixel checked against a shadow interval) and kMaskMismatch (red: failed).
    image::Image mask;
};

// The colours of CompareResult::mask, RGBA.
inline constexpr std::array<uint8_t, 4> kMaskBackground = {32, 32, 32, 255};
inline constexpr std::array<uint8_t, 4> kMaskInterior = {128, 128, 128, 255};
inline constexpr std::array<uint8_t, 4> kMaskEdge = {240, 200, 40, 255};
inline constexpr std::array<uint8_t, 4> kMaskInterval = {40, 190, 240, 255};
inline constexpr std::array<uint8_t, 4> kMaskMismatch = {255, 0, 0, 255};

// Compares |rendered| (Rgba8 as read back, or RgbaFloat) with |reference| (RgbaFloat) pixel by
// pixel: Interior and Background pixels must be within |tolerance.interiorLsb| on every channel;
// Edge pixels must match the reference at the same pixel or one of its 8 neighbours within
// |tolerance.edgeLsb|; the mean signed error over interior pixels must be within
// ±|tolerance.meanLsb|. With |referenceHigh|, each reference pixel is the interval from
// |reference| to |referenceHigh| (shadow taps that could go either way): the error is the
// distance to it, and interior interval pixels stay out of the mean. Images of different sizes
// fail with a message and no diff.
CompareResult compareImages(const image::Image& rendered, const image::Image& reference,
                            const Classification& classes, const Tolerance& tolerance = {},
                            const image::Image* referenceHigh = nullptr);

}  // namespace varc::reference
