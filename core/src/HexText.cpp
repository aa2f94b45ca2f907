// SPDX-License-Identifier: Apache-2.0
// Hexadecimal text of 64-bit values (hashes, cache keys).
#include "varc/core/HexText.h"

namespace varc {

std::string hex64(uint64_t value) {
    static constexpr char kDigits[] = "0123456789abcdef";
    std::string text;
    text.reserve(16);
    for (int shift = 60; shift >= 0; shift -= 4) text.push_back(kDigits[(value >> shift) & 0xf]);
    return text;
}

}  // namespace varc
