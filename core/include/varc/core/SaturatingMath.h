// SPDX-License-Identifier: Apache-2.0
// Variant counts multiply until they no longer fit, then stay at UINT64_MAX.
#pragma once

#include <cstdint>
#include <limits>

namespace varc::variants {

// a * b, or UINT64_MAX when the product overflows. 0 times anything is 0.
inline uint64_t saturatingMultiply(uint64_t a, uint64_t b) {
    if (a != 0 && b > std::numeric_limits<uint64_t>::max() / a) {
        return std::numeric_limits<uint64_t>::max();
    }
    return a * b;
}

}  // namespace varc::variants
