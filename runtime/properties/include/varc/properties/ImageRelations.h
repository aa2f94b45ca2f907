// SPDX-License-Identifier: Apache-2.0
// ImageRelations: the image maths of the property checks: a relation's expected image as a
// weighted sum of renders, compared with the render that must equal it within a tolerance.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "varc/image/Image.h"

namespace varc::properties {

// One term of an expected image: |weight| x |image|.
struct Term {
    const image::Image* image = nullptr;
    float weight = 1.0f;
};

// What a pixel may differ by: |absolute| + |relative| x (sum over the terms of |weight x value|),
// per channel, in the images' units (8-bit channels as value / 255). With |neighbourhood| 1 a
// pixel also passes when a pixel of the 3x3 window around it in the other image matches (edges
// that move by a pixel under a transform), checked in both directions.
struct Tolerance {
    float absolute = 0.0f;
    float relative = 0.0f;
    int neighbourhood = 0;
    // Pixels where any term, the expected sum or the actual image has a channel >=
    // |saturation| are not compared
    // (8-bit targets clamp at 1; the default compares everything).
    float saturation = 3.0e38f;
};

struct PixelError {
    uint32_t x = 0, y = 0;
    int channel = 0;  // 0 R, 1 G, 2 B
    float expected = 0, actual = 0, allowed = 0;
};

struct RelationCheck {
    bool passed = true;
    size_t comparedPixels = 0;  // pixels not skipped as saturated
    size_t failingPixels = 0;
    std::vector<PixelError> worst;  // up to kWorstPixels failing pixels, largest excess first
    image::Image expected;          // RgbaFloat: the weighted sum of the terms
    image::Image diff;              // Rgba8: |actual - expected| x 16, red where failing
    // "passed (4096 pixels)" or "12 of 4096 pixels differ; worst: (31,20) G expected 0.25 got
    // 0.5 (allowed 0.001); ..."
    std::string summary() const;
};

inline constexpr size_t kWorstPixels = 5;

// Compares |actual| with the sum of |terms| (RGB channels only: alpha is not a lit value). All
// images must have |actual|'s size (VARC_CHECK). A NaN anywhere fails its pixel.
RelationCheck checkRelation(const image::Image& actual, const std::vector<Term>& terms,
                            const Tolerance& tolerance);

// |image| flipped left to right: pixel (x, y) moves to (width - 1 - x, y).
image::Image flippedLeftRight(const image::Image& image);

// Square |image| turned a quarter turn clockwise on screen (rows down): pixel (x, y) moves to
// (size - 1 - y, x). VARC_CHECK: width == height.
image::Image quarterTurned(const image::Image& image);

// The pixels of |image| (any format) that hold a NaN or an infinity in any channel.
struct NonFinite {
    size_t count = 0;
    uint32_t firstX = 0, firstY = 0;
};
NonFinite findNonFinite(const image::Image& image);

// The pixels where some RGB channel of |a| and |b| differ by more than |by| (either way; 8-bit
// channels as value / 255); both of one size (VARC_CHECK).
size_t pixelsChanged(const image::Image& a, const image::Image& b, float by);

// How a light's contribution (its render minus the unlit render) changes when its intensity
// doubles: the pixels where some channel of |twice| is below |once| by more than |absolute| +
// |relative| x (|once| + |twice|) (the contribution shrank), and those where some channel of
// |twice| exceeds |once| by more than |by| (it grew). All three of one size (VARC_CHECK).
struct Growth {
    size_t shrinking = 0;
    size_t growing = 0;
};
Growth contributionGrowth(const image::Image& once, const image::Image& twice, float absolute,
                          float relative, float by);

// The pixels where some RGB channel of |lit| exceeds the same channel of |unlit| by more than
// |by| (8-bit channels as value / 255); both of one size (VARC_CHECK).
size_t pixelsBrighter(const image::Image& lit, const image::Image& unlit, float by);

}  // namespace varc::properties
