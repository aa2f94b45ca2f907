// SPDX-License-Identifier: Apache-2.0
// VariantSpace: Unity's enumeration order, skips, canonical keys, counting and saturation.
#include <gtest/gtest.h>

#include <limits>

#include "VariantsTestSupport.h"
#include "varc/core/JoinWords.h"
#include "varc/variants/VariantSpace.h"

namespace varc::variants {
namespace {

using testing::listing;
using testing::spaceOf;
using Listing = std::vector<std::string>;

// |n| independent `multi_compile _ K<i>` lines.
std::vector<std::string> independentSets(size_t n) {
    std::vector<std::string> pragmas;
    for (size_t i = 0; i < n; ++i) pragmas.push_back("multi_compile _ K" + std::to_string(i));
    return pragmas;
}

TEST(VariantSpace, FirstDeclaredSetVariesSlowest) {
    std::optional<VariantSpace> space =
        spaceOf({"multi_compile _ SHADOWS_SCREEN", "multi_compile _ VERTEXLIGHT_ON"});
    ASSERT_TRUE(space);
    EXPECT_EQ(listing(*space),
              (Listing{"", "VERTEXLIGHT_ON", "SHADOWS_SCREEN", "SHADOWS_SCREEN VERTEXLIGHT_ON"}));
}

TEST(VariantSpace, CartesianProductOfABCAndDE) {
    std::optional<VariantSpace> space = spaceOf({"multi_compile A B C", "multi_compile D E"});
    ASSERT_TRUE(space);
    EXPECT_EQ(space->count(), 6u);
    EXPECT_EQ(listing(*space), (Listing{"A D", "A E", "B D", "B E", "C D", "C E"}));
}

TEST(VariantSpace, OptionsFollowDeclaredOrderWithUnderscoreWhereWritten) {
    std::optional<VariantSpace> space = spaceOf({"multi_compile Z _ A"});
    ASSERT_TRUE(space);
    EXPECT_EQ(listing(*space), (Listing{"Z", "", "A"}));
}

TEST(VariantSpace, TableIsSortedAndKeysAreCanonical) {
    std::optional<VariantSpace> space = spaceOf({"multi_compile _ ZETA", "multi_compile ALPHA MU"});
    ASSERT_TRUE(space);
    EXPECT_EQ(space->table().names(), (Listing{"ALPHA", "MU", "ZETA"}));
    std::vector<VariantKey> keys = space->enumerate();
    ASSERT_EQ(keys.size(), 4u);
    EXPECT_EQ(keys[3], space->table().keyOf({"ZETA", "MU"}));
    EXPECT_EQ(keys[3], space->table().keyOf({"MU", "ZETA"}));
}

TEST(VariantSpace, SkipVariantsDropsEveryVariantWithTheKeyword) {
    std::optional<VariantSpace> space =
        spaceOf({"skip_variants B", "multi_compile _ A B", "multi_compile _ C"});
    ASSERT_TRUE(space);
    EXPECT_EQ(space->fullCount(), 6u);
    EXPECT_EQ(space->count(), 4u);
    EXPECT_EQ(listing(*space), (Listing{"", "C", "A", "A C"}));
    EXPECT_EQ(space->table().indexOf("B"), std::nullopt);
}

TEST(VariantSpace, SkippingAnUndeclaredKeywordIsHarmless) {
    std::optional<VariantSpace> space = spaceOf({"multi_compile _ A", "skip_variants NOT_HERE"});
    ASSERT_TRUE(space);
    EXPECT_EQ(space->count(), 2u);
}

TEST(VariantSpace, SkippingEveryOptionOfASetLeavesNoVariant) {
    std::optional<VariantSpace> space =
        spaceOf({"multi_compile A B", "multi_compile _ C", "skip_variants A B"});
    ASSERT_TRUE(space);
    EXPECT_EQ(space->count(), 0u);
    EXPECT_TRUE(space->enumerate().empty());
    EXPECT_EQ(space->fullCount(), 4u);
}

TEST(VariantSpace, SetOptionsParallelThePassSets) {
    std::optional<VariantSpace> space =
        spaceOf({"multi_compile _ A B", "multi_compile_fog", "skip_variants A"});
    ASSERT_TRUE(space);
    const auto& options = space->setOptions();
    ASSERT_EQ(options.size(), 2u);
    ASSERT_EQ(options[0].size(), 2u);
    EXPECT_TRUE(options[0][0].empty());
    EXPECT_EQ(options[0][1], space->table().keyOf({"B"}));
    EXPECT_EQ(options[1].size(), 4u);
}

TEST(VariantSpace, NoSetsMeansOneEmptyVariant) {
    std::optional<VariantSpace> space = spaceOf({"vertex vert"});
    ASSERT_TRUE(space);
    EXPECT_EQ(space->count(), 1u);
    EXPECT_EQ(space->fullCount(), 1u);
    EXPECT_EQ(listing(*space), (Listing{""}));
}

TEST(VariantSpace, ForEachStopsWhenTheVisitorSaysSo) {
    std::optional<VariantSpace> space = spaceOf(independentSets(10));
    ASSERT_TRUE(space);
    size_t visited = 0;
    space->forEach([&](const VariantKey&) { return ++visited < 5; });
    EXPECT_EQ(visited, 5u);
}

TEST(VariantSpace, CountsTwoToTheEighteenWithoutEnumerating) {
    std::optional<VariantSpace> space = spaceOf(independentSets(18));
    ASSERT_TRUE(space);
    EXPECT_EQ(space->count(), uint64_t{1} << 18);
    EXPECT_EQ(space->fullCount(), uint64_t{1} << 18);
    size_t visited = 0;
    VariantKey last;
    space->forEach([&](const VariantKey& key) {
        ++visited;
        last = key;
        return true;
    });
    EXPECT_EQ(visited, size_t{1} << 18);
    EXPECT_EQ(last.count(), 18u);
}

TEST(VariantSpace, CountsSaturateAtUint64Max) {
    std::optional<VariantSpace> exact = spaceOf(independentSets(63));
    ASSERT_TRUE(exact);
    EXPECT_EQ(exact->count(), uint64_t{1} << 63);
    std::optional<VariantSpace> saturated = spaceOf(independentSets(64));
    ASSERT_TRUE(saturated);
    EXPECT_EQ(saturated->count(), std::numeric_limits<uint64_t>::max());
    EXPECT_EQ(saturated->fullCount(), std::numeric_limits<uint64_t>::max());
    std::vector<std::string> withRules = independentSets(100);
    withRules.push_back("multi_compile_lightpass");
    EXPECT_EQ(spaceOf(withRules)->count(), std::numeric_limits<uint64_t>::max());
}

TEST(VariantSpace, SaturatedCountStillDropsToZeroWhenASetIsEmpty) {
    std::vector<std::string> pragmas = independentSets(70);
    pragmas.push_back("multi_compile X Y");
    pragmas.push_back("skip_variants X Y");
    EXPECT_EQ(spaceOf(pragmas)->count(), 0u);
}

TEST(VariantSpace, IndependentSetsMultiplyWithRuleLinkedGroups) {
    std::optional<VariantSpace> space =
        spaceOf({"multi_compile _ A", "multi_compile_fwdadd_fullshadows", "multi_compile_fog"});
    ASSERT_TRUE(space);
    EXPECT_EQ(space->count(), 2u * 13u * 4u);
    EXPECT_EQ(space->enumerate().size(), 2u * 13u * 4u);
}

TEST(VariantSpace, MoreThan256KeywordsIsAnError) {
    std::vector<std::string> pragmas = independentSets(256);
    pragmas.push_back("multi_compile _ ONE_TOO_MANY");
    DiagnosticList sink;
    std::optional<PassKeywords> keywords = testing::parse(pragmas, sink);
    ASSERT_TRUE(keywords);
    EXPECT_FALSE(VariantSpace::build(*keywords, sink));
    ASSERT_EQ(sink.errorCount(), 1u);
    EXPECT_EQ(sink.diagnostics()[0].location.line, 257u);
    EXPECT_NE(sink.diagnostics()[0].message.find("ONE_TOO_MANY"), std::string::npos);
}

TEST(VariantSpace, ExactlyTwoHundredFiftySixKeywordsFit) {
    std::optional<VariantSpace> space = spaceOf(independentSets(256));
    ASSERT_TRUE(space);
    EXPECT_EQ(space->table().size(), 256u);
}

TEST(VariantSpace, OptionsOfDecodesOneOptionPerSet) {
    std::optional<VariantSpace> space = spaceOf({"multi_compile _ A", "multi_compile B C"});
    ASSERT_TRUE(space);
    const KeywordTable& table = space->table();
    EXPECT_EQ(space->optionsOf(table.keyOf({"A", "C"})), (std::vector<size_t>{1, 1}));
    EXPECT_EQ(space->optionsOf(table.keyOf({"B"})), (std::vector<size_t>{0, 0}));
    EXPECT_EQ(space->optionsOf(table.keyOf({"A"})), std::nullopt);  // `B C` has no `_`
    EXPECT_EQ(space->optionsOf(table.keyOf({"B", "C"})), std::nullopt);
}

TEST(VariantSpace, ContainsAppliesTheValidityRules) {
    std::optional<VariantSpace> space = spaceOf({"multi_compile_fwdadd_fullshadows"});
    ASSERT_TRUE(space);
    const KeywordTable& table = space->table();
    EXPECT_TRUE(space->contains(table.keyOf({"SPOT", "SHADOWS_DEPTH"})));
    EXPECT_FALSE(space->contains(table.keyOf({"POINT", "SHADOWS_DEPTH"})));
    size_t contained = 0;
    space->forEach([&](const VariantKey& key) {
        contained += space->contains(key) ? 1 : 0;
        return true;
    });
    EXPECT_EQ(contained, 13u);
}

TEST(VariantSpace, PinnedCombinationsKeepTheSpaceOrder) {
    // Sets 0 and 2 pinned to (0,1), (1,0), (1,1): 3 combinations · 2 options of set 1 = 6.
    std::optional<VariantSpace> space =
        spaceOf({"multi_compile _ A", "multi_compile _ M", "multi_compile _ C"});
    ASSERT_TRUE(space);
    VariantSpace::Pins pins{{0, 2}, {{0, 1}, {1, 0}, {1, 1}}};
    std::vector<std::string> lines;
    space->forEachPinned(pins, [&](const VariantKey& key) {
        lines.push_back(joinWords(space->table().namesOf(key)));
        return true;
    });
    EXPECT_EQ(lines, (Listing{"C", "C M", "A", "A C", "A M", "A C M"}));
    EXPECT_EQ(space->countPinned({0, 2}, {1, 0}), 2u);
    EXPECT_EQ(space->countPinned({}, {}), 8u);
}

}  // namespace
}  // namespace varc::variants
