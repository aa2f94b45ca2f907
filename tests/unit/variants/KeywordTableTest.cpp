// SPDX-License-Identifier: Apache-2.0
// KeywordTable: name <-> bit mapping, requested-keyword restriction, the bit layout table.
#include <gtest/gtest.h>

#include "varc/variants/VariantSpace.h"

namespace varc::variants {
namespace {

KeywordTable fogTable() { return KeywordTable({"FOG_EXP", "FOG_EXP2", "FOG_LINEAR"}); }

TEST(KeywordTable, IndexIsSortedPosition) {
    KeywordTable table = fogTable();
    EXPECT_EQ(table.size(), 3u);
    EXPECT_EQ(table.indexOf("FOG_EXP"), 0u);
    EXPECT_EQ(table.indexOf("FOG_EXP2"), 1u);
    EXPECT_EQ(table.indexOf("FOG_LINEAR"), 2u);
    EXPECT_EQ(table.indexOf("FOG"), std::nullopt);
    EXPECT_EQ(table.indexOf("FOG_LINEAR_X"), std::nullopt);
    EXPECT_EQ(table.name(1), "FOG_EXP2");
}

TEST(KeywordTable, KeyOfIgnoresUndeclaredAndOrder) {
    KeywordTable table = fogTable();
    VariantKey key = table.keyOf({"FOG_LINEAR", "NOT_DECLARED", "FOG_EXP"});
    EXPECT_EQ(key.count(), 2u);
    EXPECT_TRUE(key.test(0));
    EXPECT_TRUE(key.test(2));
    EXPECT_EQ(key, table.keyOf({"FOG_EXP", "FOG_LINEAR"}));
    EXPECT_TRUE(table.keyOf({"NOPE"}).empty());
}

TEST(KeywordTable, NamesOfIsSorted) {
    KeywordTable table = fogTable();
    std::vector<std::string> expected = {"FOG_EXP", "FOG_LINEAR"};
    EXPECT_EQ(table.namesOf(table.keyOf({"FOG_LINEAR", "FOG_EXP"})), expected);
    EXPECT_TRUE(table.namesOf(VariantKey{}).empty());
}

TEST(KeywordTable, BitLayoutTableIsFilamentStyle) {
    std::string expected =
        "+-----+------------+\n"
        "| bit | keyword    |\n"
        "+-----+------------+\n"
        "|   0 | FOG_EXP    |\n"
        "|   1 | FOG_EXP2   |\n"
        "|   2 | FOG_LINEAR |\n"
        "+-----+------------+\n";
    EXPECT_EQ(fogTable().bitLayoutTable(), expected);
}

TEST(KeywordTable, EmptyTableLayoutHasHeaderOnly) {
    std::string expected =
        "+-----+---------+\n"
        "| bit | keyword |\n"
        "+-----+---------+\n";
    EXPECT_EQ(KeywordTable({}).bitLayoutTable(), expected);
}

TEST(KeywordTableDeathTest, UnsortedNamesAreAProgrammerError) {
    EXPECT_DEATH(KeywordTable({"B", "A"}), "sorted");
}

}  // namespace
}  // namespace varc::variants
