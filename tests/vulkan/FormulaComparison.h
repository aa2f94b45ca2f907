// SPDX-License-Identifier: Apache-2.0
// Compares a float image drawn over a full-target quad with a CPU formula of the pixel centre's
// (u, v), for the built-in API value tests.
#pragma once

#include <array>
#include <functional>
#include <string>

#include "varc/image/Image.h"

namespace varc::render::testing {

using FormulaValue = std::array<double, 4>;
using PixelFormula = std::function<FormulaValue(double u, double v)>;

struct FormulaComparison {
    // The largest error over the pixels and channels compared, in units of the allowance
    // |absolute| + |relative| * |expected| (<= 1 passes), and where it is.
    double worst = 0;
    std::string where;
    double largest = 0;  // the largest |expected| value: a formula of nothing proves nothing
};

// Compares the first |channels| channels of every pixel of |image| with |formula| at the pixel's
// centre, u = (x + 0.5) / width and v = (y + 0.5) / height.
FormulaComparison compareWithFormula(const image::Image& image, const PixelFormula& formula,
                                     int channels, double absolute, double relative);

}  // namespace varc::render::testing
