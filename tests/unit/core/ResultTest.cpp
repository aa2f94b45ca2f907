// SPDX-License-Identifier: Apache-2.0
// Result<T> holds either a value or an Error and refuses the wrong access.
#include "varc/core/Result.h"

#include <gtest/gtest.h>

namespace varc {
namespace {

Result<int> parsePositive(int value) {
    if (value <= 0) return makeError(ErrorCode::InvalidInput, "not positive");
    return value;
}

TEST(Result, HoldsValue) {
    Result<int> r = parsePositive(3);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(*r, 3);
}

TEST(Result, HoldsError) {
    Result<int> r = parsePositive(-1);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().code, ErrorCode::InvalidInput);
    EXPECT_EQ(r.error().detail, "not positive");
}

TEST(ResultDeathTest, ValueOnErrorAborts) {
    Result<int> r = parsePositive(0);
    EXPECT_DEATH((void)r.value(), "not positive");
}

}  // namespace
}  // namespace varc
