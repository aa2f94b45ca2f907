// SPDX-License-Identifier: Apache-2.0
// ImageRelations: weighted sums of renders compared with a render, pixel by pixel or within a
// 3x3 window, and the search for NaN and infinity.
#include "varc/properties/ImageRelations.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <utility>

#include "varc/core/Check.h"

namespace varc::properties {

namespace {

using image::Image;
using image::PixelFormat;

// |image| as floats (8-bit channels as value / 255).
std::vector<float> floatsOf(const Image& image) {
    if (image.isFloat()) return {image.floats().begin(), image.floats().end()};
    std::vector<float> values(image.bytes().size());
    for (size_t i = 0; i < values.size(); ++i)
        values[i] = static_cast<float>(image.bytes()[i]) / 255.0f;
    return values;
}

struct Planes {
    uint32_t width = 0, height = 0;
    std::vector<float> actual, expected, magnitude;
    std::vector<bool> skipped;  // per pixel: saturated
};

Planes combine(const Image& actual, const std::vector<Term>& terms, const Tolerance& tolerance) {
    Planes planes;
    planes.width = actual.width();
    planes.height = actual.height();
    planes.actual = floatsOf(actual);
    planes.expected.assign(planes.actual.size(), 0.0f);
    planes.magnitude.assign(planes.actual.size(), 0.0f);
    planes.skipped.assign(planes.actual.size() / 4, false);
    auto markSaturated = [&](const std::vector<float>& values) {
        for (size_t i = 0; i < values.size(); ++i)
            // An infinity is a failure to report, never a clamped value.
            if (i % 4 != 3 && std::isfinite(values[i]) && values[i] >= tolerance.saturation)
                planes.skipped[i / 4] = true;
    };
    markSaturated(planes.actual);
    for (const Term& term : terms) {
        VARC_CHECK(term.image && term.image->width() == actual.width() &&
                   term.image->height() == actual.height());
        std::vector<float> values = floatsOf(*term.image);
        markSaturated(values);
        for (size_t i = 0; i < values.size(); ++i) {
            planes.expected[i] += term.weight * values[i];
            planes.magnitude[i] += std::abs(term.weight * values[i]);
        }
    }
    markSaturated(planes.expected);  // a sum the target would clamp
    return planes;
}

// The excess of |value| over the allowed difference from |target| (<= 0 passes; NaN fails).
float excess(float value, float target, float allowed) {
    float difference = std::abs(value - target);
    if (std::isnan(difference)) return 3.0e38f;
    return difference - allowed;
}

// The smallest excess of pixel (x, y) channel c of |from| against the window of |to|.
float windowExcess(const Planes& p, const std::vector<float>& from, const std::vector<float>& to,
                   uint32_t x, uint32_t y, int c, float allowed, int radius) {
    const size_t index = (static_cast<size_t>(y) * p.width + x) * 4 + static_cast<size_t>(c);
    float best = 3.0e38f;
    for (int dy = -radius; dy <= radius; ++dy) {
        for (int dx = -radius; dx <= radius; ++dx) {
            const int64_t nx = int64_t{x} + dx, ny = int64_t{y} + dy;
            if (nx < 0 || ny < 0 || nx >= p.width || ny >= p.height) continue;
            const size_t other = (static_cast<size_t>(ny) * p.width + static_cast<size_t>(nx)) * 4 +
                                 static_cast<size_t>(c);
            best = std::min(best, excess(to[other], from[index], allowed));
        }
    }
    return best;
}

Image diffImage(const Planes& p, const std::vector<bool>& failing) {
    Image diff(p.width, p.height, PixelFormat::Rgba8);
    for (uint32_t y = 0; y < p.height; ++y) {
        for (uint32_t x = 0; x < p.width; ++x) {
            const size_t pixel = static_cast<size_t>(y) * p.width + x;
            std::array<uint8_t, 4> rgba{0, 0, 0, 255};
            for (int c = 0; c < 3; ++c) {
                float d = std::abs(p.actual[pixel * 4 + static_cast<size_t>(c)] -
                                   p.expected[pixel * 4 + static_cast<size_t>(c)]);
                float scaled = std::isnan(d) ? 255.0f : std::min(255.0f, d * 16.0f * 255.0f);
                rgba[static_cast<size_t>(c)] = static_cast<uint8_t>(scaled);
            }
            if (failing[pixel]) rgba = {255, 0, 0, 255};
            diff.setPixel8(x, y, rgba);
        }
    }
    return diff;
}

Image expectedImage(const Planes& p) {
    Image expected(p.width, p.height, PixelFormat::RgbaFloat);
    std::copy(p.expected.begin(), p.expected.end(), expected.floats().begin());
    for (size_t i = 3; i < p.expected.size(); i += 4) expected.floats()[i] = 1.0f;
    return expected;
}

}  // namespace

RelationCheck checkRelation(const Image& actual, const std::vector<Term>& terms,
                            const Tolerance& tolerance) {
    Planes p = combine(actual, terms, tolerance);
    RelationCheck check;
    std::vector<bool> failing(p.skipped.size(), false);
    std::vector<std::pair<float, PixelError>> errors;
    for (uint32_t y = 0; y < p.height; ++y) {
        for (uint32_t x = 0; x < p.width; ++x) {
            const size_t pixel = static_cast<size_t>(y) * p.width + x;
            if (p.skipped[pixel]) continue;
            ++check.comparedPixels;
            std::pair<float, PixelError> worstHere{0.0f, {}};
            for (int c = 0; c < 3; ++c) {
                const size_t i = pixel * 4 + static_cast<size_t>(c);
                const float allowed = tolerance.absolute + tolerance.relative * p.magnitude[i];
                float over = excess(p.actual[i], p.expected[i], allowed);
                if (over > 0 && tolerance.neighbourhood > 0) {
                    over = std::max(windowExcess(p, p.expected, p.actual, x, y, c, allowed,
                                                 tolerance.neighbourhood),
                                    windowExcess(p, p.actual, p.expected, x, y, c, allowed,
                                                 tolerance.neighbourhood));
                }
                if (over > worstHere.first)
                    worstHere = {over, {x, y, c, p.expected[i], p.actual[i], allowed}};
            }
            if (worstHere.first > 0) {
                failing[pixel] = true;
                errors.push_back(worstHere);
            }
        }
    }
    check.failingPixels = errors.size();
    check.passed = errors.empty();
    std::stable_sort(errors.begin(), errors.end(),
                     [](const auto& a, const auto& b) { return a.first > b.first; });
    for (size_t i = 0; i < errors.size() && i < kWorstPixels; ++i)
        check.worst.push_back(errors[i].second);
    check.expected = expectedImage(p);
    check.diff = diffImage(p, failing);
    return check;
}

std::string RelationCheck::summary() const {
    char text[160];
    if (passed) {
        std::snprintf(text, sizeof text, "passed (%zu pixels)", comparedPixels);
        return text;
    }
    std::snprintf(text, sizeof text, "%zu of %zu pixels differ; worst:", failingPixels,
                  comparedPixels);
    std::string result = text;
    static const char kChannels[] = "RGB";
    for (const PixelError& e : worst) {
        std::snprintf(text, sizeof text, " (%u,%u) %c expected %.5g got %.5g (allowed %.3g);", e.x,
                      e.y, kChannels[e.channel], static_cast<double>(e.expected),
                      static_cast<double>(e.actual), static_cast<double>(e.allowed));
        result += text;
    }
    result.pop_back();
    return result;
}

size_t pixelsBrighter(const Image& lit, const Image& unlit, float by) {
    VARC_CHECK(lit.width() == unlit.width() && lit.height() == unlit.height());
    const std::vector<float> a = floatsOf(lit), b = floatsOf(unlit);
    size_t count = 0;
    for (size_t i = 0; i < a.size(); i += 4) {
        bool brighter = false;
        for (size_t c = 0; c < 3; ++c) brighter = brighter || a[i + c] - b[i + c] > by;
        if (brighter) ++count;
    }
    return count;
}

size_t pixelsChanged(const Image& a, const Image& b, float by) {
    VARC_CHECK(a.width() == b.width() && a.height() == b.height());
    const std::vector<float> x = floatsOf(a), y = floatsOf(b);
    size_t count = 0;
    for (size_t i = 0; i < x.size(); i += 4) {
        bool changed = false;
        for (size_t c = 0; c < 3; ++c) changed = changed || !(std::abs(x[i + c] - y[i + c]) <= by);
        if (changed) ++count;
    }
    return count;
}

Growth contributionGrowth(const Image& once, const Image& twice, float absolute, float relative,
                          float by) {
    VARC_CHECK(once.width() == twice.width() && once.height() == twice.height());
    const std::vector<float> a = floatsOf(once), b = floatsOf(twice);
    Growth growth;
    for (size_t i = 0; i < a.size(); i += 4) {
        bool shrinks = false, grows = false;
        for (size_t c = 0; c < 3; ++c) {
            const float allowed = absolute + relative * (std::abs(a[i + c]) + std::abs(b[i + c]));
            // A NaN counts as shrinking: it never passes for monotone growth.
            shrinks = shrinks || !(b[i + c] >= a[i + c] - allowed);
            grows = grows || b[i + c] - a[i + c] > by;
        }
        if (shrinks) ++growth.shrinking;
        if (grows) ++growth.growing;
    }
    return growth;
}

namespace {

// |image| with each pixel (x, y) moved to |target|(x, y), a permutation of the pixel grid.
template <typename TargetOf>
Image remapped(const Image& image, TargetOf target) {
    Image result = image;
    const size_t channels = 4;
    auto remap = [&](auto source, auto destination) {
        for (size_t y = 0; y < image.height(); ++y)
            for (size_t x = 0; x < image.width(); ++x) {
                const auto [tx, ty] = target(x, y);
                for (size_t c = 0; c < channels; ++c)
                    destination[(ty * image.width() + tx) * channels + c] =
                        source[(y * image.width() + x) * channels + c];
            }
    };
    if (image.isFloat())
        remap(image.floats(), result.floats());
    else
        remap(image.bytes(), result.bytes());
    return result;
}

}  // namespace

Image flippedLeftRight(const Image& image) {
    const size_t width = image.width();
    return remapped(image, [&](size_t x, size_t y) { return std::pair(width - 1 - x, y); });
}

Image quarterTurned(const Image& image) {
    VARC_CHECK(image.width() == image.height());
    const size_t size = image.width();
    return remapped(image, [&](size_t x, size_t y) { return std::pair(size - 1 - y, x); });
}

NonFinite findNonFinite(const Image& image) {
    NonFinite found;
    if (!image.isFloat()) return found;  // 8-bit values are always finite
    const auto values = image.floats();
    for (size_t i = 0; i < values.size(); i += 4) {
        bool bad = false;
        for (size_t c = 0; c < 4; ++c) bad = bad || !std::isfinite(values[i + c]);
        if (!bad) continue;
        if (found.count == 0) {
            found.firstX = static_cast<uint32_t>((i / 4) % image.width());
            found.firstY = static_cast<uint32_t>((i / 4) / image.width());
        }
        ++found.count;
    }
    return found;
}

}  // namespace varc::properties
