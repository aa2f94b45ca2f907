// SPDX-License-Identifier: Apache-2.0
// Counts that add and multiply until they no longer fit, then stay at UINT64_MAX: variant
// counts of huge keyword spaces are reported as "at least 2^64 - 1", never wrapped around.
#pragma once

#include <cstdint>
#include <limits>

namespace varc {

inline constexpr uint64_t kSaturated = std::numeric_limits<uint64_t>::max();

// a * b, or kSaturated when the product overflows. 0 times anything is 0.
constexpr uint64_t saturatingMultiply(uint64_t a, uint64_t b) {
    if (a != 0 && b > kSaturated / a) return kSaturated;
    return a * b;
}

// a + b, or kSaturated when the sum overflows.
constexpr uint64_t saturatingAdd(uint64_t a, uint64_t b) {
    return b > kSaturated - a ? kSaturated : a + b;
}

}  // namespace varc
