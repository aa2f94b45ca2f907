// SPDX-License-Identifier: Apache-2.0
// displayKeywords: the no-keyword entry written `_`, order kept.
#include "varc/core/KeywordNames.h"

#include <gtest/gtest.h>

namespace varc {
namespace {

TEST(KeywordNames, NoKeywordEntryIsWrittenUnderscore) {
    EXPECT_EQ(displayKeywords({"", "FOG_ON"}), (std::vector<std::string>{"_", "FOG_ON"}));
    EXPECT_EQ(displayKeywords({"A", "", "B"}), (std::vector<std::string>{"A", "_", "B"}));
}

TEST(KeywordNames, EmptyListStaysEmpty) { EXPECT_TRUE(displayKeywords({}).empty()); }

}  // namespace
}  // namespace varc
