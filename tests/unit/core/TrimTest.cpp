// SPDX-License-Identifier: Apache-2.0
// trim and trimRight: the default ASCII whitespace set and caller-chosen sets.
#include "varc/core/Trim.h"

#include <gtest/gtest.h>

namespace varc {
namespace {

TEST(Trim, RemovesAsciiWhitespaceFromBothEnds) {
    EXPECT_EQ(trim("  a b \n"), "a b");
    EXPECT_EQ(trim("\t\v\f\r\nx\r\n"), "x");
    EXPECT_EQ(trim("x"), "x");
}

TEST(Trim, AllWhitespaceOrEmptyGivesEmpty) {
    EXPECT_EQ(trim(" \t\n"), "");
    EXPECT_EQ(trim(""), "");
    EXPECT_EQ(trimRight(" \t"), "");
}

TEST(Trim, KeepsInnerWhitespace) { EXPECT_EQ(trim(" a \n b "), "a \n b"); }

TEST(Trim, UsesTheGivenSet) {
    EXPECT_EQ(trim("\n a \n", " "), "\n a \n");
    EXPECT_EQ(trim("\v a\v", " \t\r\n\f"), "\v a\v");
    EXPECT_EQ(trim("-+a+-", "+-"), "a");
}

TEST(Trim, RightOnlyLeavesTheStart) {
    EXPECT_EQ(trimRight(" a \r"), " a");
    EXPECT_EQ(trimRight("a \n", " \t\r"), "a \n");
}

TEST(Trim, ReturnsAViewIntoTheText) {
    const std::string_view text = "  abc  ";
    EXPECT_EQ(trim(text).data(), text.data() + 2);
}

}  // namespace
}  // namespace varc
