// SPDX-License-Identifier: Apache-2.0
// Hexadecimal text of 64-bit values (hashes, cache keys).
#pragma once

#include <cstdint>
#include <string>

namespace varc {

// |value| as 16 lowercase hexadecimal digits, zero-padded: hex64(0xAB) == "00000000000000ab".
std::string hex64(uint64_t value);

}  // namespace varc
