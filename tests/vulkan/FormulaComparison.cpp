// SPDX-License-Identifier: Apache-2.0
// compareWithFormula: the per-pixel comparison the built-in API value tests share.
#include "FormulaComparison.h"

#include <algorithm>
#include <cmath>

namespace varc::render::testing {

FormulaComparison compareWithFormula(const image::Image& image, const PixelFormula& formula,
                                     int channels, double absolute, double relative) {
    FormulaComparison result;
    for (uint32_t y = 0; y < image.height(); ++y) {
        for (uint32_t x = 0; x < image.width(); ++x) {
            double u = (x + 0.5) / image.width(), v = (y + 0.5) / image.height();
            FormulaValue want = formula(u, v);
            std::array<float, 4> got = image.pixelFloat(x, y);
            for (size_t c = 0; c < static_cast<size_t>(channels); ++c) {
                double error =
                    std::abs(got[c] - want[c]) / (absolute + relative * std::abs(want[c]));
                result.largest = std::max(result.largest, std::abs(want[c]));
                if (error > result.worst) {
                    result.worst = error;
                    result.where = "pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                                   ") channel " + std::to_string(c) + ": GPU " +
                                   std::to_string(got[c]) + ", CPU " + std::to_string(want[c]);
                }
            }
        }
    }
    return result;
}

}  // namespace varc::render::testing
