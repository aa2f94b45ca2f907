// SPDX-License-Identifier: Apache-2.0
// hex64: 16 lowercase, zero-padded hexadecimal digits.
#include "varc/core/HexText.h"

#include <gtest/gtest.h>

namespace varc {
namespace {

TEST(HexText, SixteenLowercaseDigitsZeroPadded) {
    EXPECT_EQ(hex64(0), "0000000000000000");
    EXPECT_EQ(hex64(0xAB), "00000000000000ab");
    EXPECT_EQ(hex64(0x0123456789ABCDEFull), "0123456789abcdef");
    EXPECT_EQ(hex64(~uint64_t{0}), "ffffffffffffffff");
}

}  // namespace
}  // namespace varc
