// SPDX-License-Identifier: Apache-2.0
// ImageCompare: per-class tolerances, edge neighbourhood matching, mean-error check, diff image.
#include "varc/reference/ImageCompare.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace varc::reference {
namespace {

const char* className(PixelClass c) {
    switch (c) {
        case PixelClass::Background:
            return "background";
        case PixelClass::Edge:
            return "edge";
        case PixelClass::Interior:
            return "interior";
    }
    return "?";
}

// Largest per-channel distance in LSB from |a| to the interval [low, high] (a point when equal),
// and the signed error of that channel.
std::pair<float, float> channelError(const std::array<float, 4>& a, const std::array<float, 4>& low,
                                     const std::array<float, 4>& high, int channels) {
    float worst = 0.0f, signedWorst = 0.0f;
    for (int c = 0; c < channels; ++c) {
        const float lo = std::min(low[c], high[c]), hi = std::max(low[c], high[c]);
        const float nearest = std::isnan(a[c]) ? lo : std::clamp(a[c], lo, hi);
        const float e = (a[c] - nearest) * 255.0f;
        if (std::abs(e) > worst || std::isnan(e)) {
            worst = std::isnan(e) ? INFINITY : std::abs(e);
            signedWorst = e;
        }
    }
    return {worst, signedWorst};
}

std::string describe(const PixelFailure& f) {
    std::ostringstream s;
    s.precision(4);
    s << "(" << f.x << ", " << f.y << ") " << className(f.pixelClass) << ": rendered ("
      << f.rendered[0] * 255.0f << ", " << f.rendered[1] * 255.0f << ", " << f.rendered[2] * 255.0f
      << ") reference (" << f.reference[0] * 255.0f << ", " << f.reference[1] * 255.0f << ", "
      << f.reference[2] * 255.0f << "), " << f.errorLsb << " LSB";
    return s.str();
}

uint8_t diffLevel(float lsb) {
    return static_cast<uint8_t>(std::min(255.0f, std::abs(lsb) * 32.0f));
}

const std::array<uint8_t, 4>& maskColour(PixelClass cls, bool interval) {
    if (cls == PixelClass::Edge) return kMaskEdge;
    if (cls == PixelClass::Interior) return interval ? kMaskInterval : kMaskInterior;
    return kMaskBackground;
}

// The diff image's pixel: the reference's luminance in dark grey, red where the render is
// brighter and blue where darker (by how much), or saturated for a failing pixel.
template <typename Pixel>
std::array<uint8_t, 4> diffPixel(const Pixel& want, float signedError, bool fails) {
    const uint8_t grey = static_cast<uint8_t>(std::clamp(
        (want[0] * 0.2126f + want[1] * 0.7152f + want[2] * 0.0722f) * 64.0f, 0.0f, 64.0f));
    std::array<uint8_t, 4> d = {grey, grey, grey, 255};
    if (signedError > 0.0f) d[0] = std::max(grey, diffLevel(signedError));
    if (signedError < 0.0f) d[2] = std::max(grey, diffLevel(signedError));
    if (fails) {
        d = {uint8_t(signedError >= 0.0f ? 255 : 0), 255, uint8_t(signedError < 0.0f ? 255 : 0),
             255};
    }
    return d;
}

// The one-line verdict of |r| over |pixels| pixels: PASS/FAIL, errors and pixel counts.
std::string summaryOf(const CompareResult& r, const Tolerance& tolerance, uint64_t pixels) {
    std::ostringstream s;
    s.precision(3);
    s << (r.passed ? "PASS" : "FAIL") << ": max error " << r.maxErrorLsb << " LSB, mean signed "
      << r.meanSignedErrorLsb << " LSB (limit ±" << tolerance.meanLsb << "), mean abs "
      << r.meanAbsErrorLsb << " LSB, " << r.failingPixels << " failing pixels of " << pixels
      << " (interior " << r.interiorPixels << ", edge " << r.edgePixels << ", background "
      << r.backgroundPixels << ")";
    if (r.intervalPixels > 0) s << ", " << r.intervalPixels << " checked by shadow interval";
    if (!r.firstFailures.empty()) s << "; first: " << describe(r.firstFailures.front());
    return s.str();
}

}  // namespace

CompareResult compareImages(const image::Image& rendered, const image::Image& reference,
                            const Classification& classes, const Tolerance& tolerance,
                            const image::Image* referenceHigh) {
    CompareResult r;
    const uint32_t w = reference.width(), h = reference.height();
    if (rendered.width() != w || rendered.height() != h || classes.width != w ||
        classes.height != h) {
        r.message = "FAIL: image sizes differ (rendered " + std::to_string(rendered.width()) + "x" +
                    std::to_string(rendered.height()) + ", reference " + std::to_string(w) + "x" +
                    std::to_string(h) + ")";
        return r;
    }
    if (referenceHigh && (referenceHigh->width() != w || referenceHigh->height() != h)) {
        r.message = "FAIL: the reference's upper-bound image has another size";
        return r;
    }
    auto high = [&](uint32_t x, uint32_t y) {
        return referenceHigh ? referenceHigh->pixelFloat(x, y) : reference.pixelFloat(x, y);
    };
    const int channels = tolerance.compareAlpha ? 4 : 3;
    r.diff = image::Image(w, h, image::PixelFormat::Rgba8);
    r.mask = image::Image(w, h, image::PixelFormat::Rgba8);
    double signedSum = 0.0, absSum = 0.0;
    uint64_t samples = 0;
    for (uint32_t y = 0; y < h; ++y) {
        for (uint32_t x = 0; x < w; ++x) {
            const PixelClass cls = classes.at(x, y);
            const auto got = rendered.pixelFloat(x, y);
            const auto want = reference.pixelFloat(x, y);
            const auto wantHigh = high(x, y);
            const bool interval = want != wantHigh;
            auto [error, signedError] = channelError(got, want, wantHigh, channels);
            float limit = tolerance.interiorLsb;
            if (cls == PixelClass::Edge) {
                ++r.edgePixels;
                limit = tolerance.edgeLsb;
                for (int dy = -1; dy <= 1; ++dy) {
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int64_t nx = int64_t{x} + dx, ny = int64_t{y} + dy;
                        if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
                        const auto ux = static_cast<uint32_t>(nx), uy = static_cast<uint32_t>(ny);
                        const auto e =
                            channelError(got, reference.pixelFloat(ux, uy), high(ux, uy), channels);
                        if (e.first < error) std::tie(error, signedError) = e;
                    }
                }
            } else if (cls == PixelClass::Interior && interval) {
                ++r.interiorPixels;
                ++r.intervalPixels;  // any value in the interval is right: not in the means
            } else if (cls == PixelClass::Interior) {
                ++r.interiorPixels;
                for (int c = 0; c < channels; ++c) {
                    const double e = (static_cast<double>(got[c]) - want[c]) * 255.0;
                    signedSum += e;
                    absSum += std::abs(e);
                    ++samples;
                }
            } else {
                ++r.backgroundPixels;
            }
            r.maxErrorLsb = std::max(r.maxErrorLsb, error);
            // 1e-3 LSB of slack: k/255 values in float do not subtract to exact multiples of 1/255.
            const bool fails = !(error <= limit + 1e-3f);
            const std::array<uint8_t, 4> d = diffPixel(want, signedError, fails);
            if (fails) {
                ++r.failingPixels;
                if (r.firstFailures.size() < tolerance.maxReported) {
                    r.firstFailures.push_back({x, y, cls, got, want, error});
                }
            }
            r.diff.setPixel8(x, y, d);
            r.mask.setPixel8(x, y, fails ? kMaskMismatch : maskColour(cls, interval));
        }
    }
    if (samples > 0) {
        r.meanSignedErrorLsb = static_cast<float>(signedSum / static_cast<double>(samples));
        r.meanAbsErrorLsb = static_cast<float>(absSum / static_cast<double>(samples));
    }
    const bool meanOk = std::abs(r.meanSignedErrorLsb) <= tolerance.meanLsb;
    r.passed = r.failingPixels == 0 && meanOk;
    r.message = summaryOf(r, tolerance, w * h);
    return r;
}

}  // namespace varc::reference
