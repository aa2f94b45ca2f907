// SPDX-License-Identifier: Apache-2.0
// selectVariant: exact hits, the closest ordering, first, and strict/exact misses.
#include <gtest/gtest.h>

#include "VariantsTestSupport.h"
#include "varc/variants/VariantSelector.h"

namespace varc::variants {
namespace {

using testing::spaceOf;

constexpr SelectionPolicy kAllPolicies[] = {SelectionPolicy::Exact, SelectionPolicy::Closest,
                                            SelectionPolicy::First, SelectionPolicy::Strict};

// A pass and its variants, with keys built from names.
struct Fixture {
    explicit Fixture(const std::vector<std::string>& pragmas)
        : space(spaceOf(pragmas).value()), variants(space.enumerate()) {}
    VariantKey key(const std::vector<std::string>& names) const {
        return space.table().keyOf(names);
    }
    Selection select(const std::vector<std::string>& names, SelectionPolicy policy) const {
        return selectVariant(variants, key(names), policy);
    }
    VariantSpace space;
    std::vector<VariantKey> variants;
};

TEST(VariantSelector, ExactMatchWinsUnderEveryPolicy) {
    Fixture f({"multi_compile _ A", "multi_compile _ B"});  // [], [B], [A], [A B]
    for (SelectionPolicy policy : kAllPolicies) {
        Selection selection = f.select({"B", "A"}, policy);
        EXPECT_EQ(selection.index, 3u) << toString(policy);
        EXPECT_TRUE(selection.exact);
        EXPECT_TRUE(selection.nearest.empty());
    }
}

TEST(VariantSelector, NeitherKeywordEnabledPicksTheFirst) {
    // docs/KEYWORDS.md §8: "neither enabled → the first one", as Unity documents it.
    Fixture f({"multi_compile FANCY_STUFF_OFF FANCY_STUFF_ON"});
    Selection selection = f.select({}, SelectionPolicy::Closest);
    EXPECT_EQ(selection.index, 0u);
    EXPECT_FALSE(selection.exact);
}

VariantKey bits(std::initializer_list<size_t> on) {
    VariantKey key;
    for (size_t bit : on) key.set(bit);
    return key;
}

TEST(VariantSelector, ClosestMaximisesSharedKeywords) {
    Fixture f({"multi_compile _ A", "multi_compile B C"});  // [B], [C], [A B], [A C]
    Selection selection = f.select({"A"}, SelectionPolicy::Closest);
    EXPECT_EQ(selection.index, 2u);
    EXPECT_FALSE(selection.exact);
    EXPECT_EQ(f.select({"C"}, SelectionPolicy::Closest).index, 1u);
    EXPECT_EQ(f.select({"C", "UNDECLARED"}, SelectionPolicy::Closest).index, 1u);
    EXPECT_TRUE(f.select({"C", "UNDECLARED"}, SelectionPolicy::Closest).exact);
}

TEST(VariantSelector, ClosestThenMinimisesExtraKeywords) {
    std::vector<VariantKey> variants = {bits({1, 2, 3}), bits({1, 2}), bits({1, 4})};
    Selection selection = selectVariant(variants, bits({1, 2, 5}), SelectionPolicy::Closest);
    EXPECT_EQ(selection.index, 1u);
    EXPECT_FALSE(selection.exact);
}

TEST(VariantSelector, SharedKeywordsOutweighExtras) {
    // [1 2 3] shares 2 with the request and has 1 extra; [2] shares 1 and has none.
    std::vector<VariantKey> variants = {bits({0}), bits({1, 2, 3}), bits({2})};
    EXPECT_EQ(selectVariant(variants, bits({1, 2, 5}), SelectionPolicy::Closest).index, 1u);
}

TEST(VariantSelector, TiesGoToTheEarliestVariant) {
    Fixture f({"multi_compile X Y Z"});
    EXPECT_EQ(f.select({}, SelectionPolicy::Closest).index, 0u);
    Fixture g({"multi_compile _ P", "multi_compile _ Q"});  // [], [Q], [P], [P Q]
    VariantKey unknown;  // nothing declared requested -> [] is exact
    EXPECT_TRUE(selectVariant(g.variants, unknown, SelectionPolicy::Closest).exact);
}

TEST(VariantSelector, FirstFallsBackToTheFirstVariant) {
    Fixture f({"multi_compile A B", "multi_compile _ C"});  // [A], [A C], [B], [B C]
    Selection selection = f.select({"C"}, SelectionPolicy::First);
    EXPECT_EQ(selection.index, 0u);
    EXPECT_FALSE(selection.exact);
    EXPECT_EQ(f.select({"C"}, SelectionPolicy::Closest).index, 1u);
}

TEST(VariantSelector, StrictAndExactMissListUpToThreeNearestBestFirst) {
    Fixture f({"multi_compile A B", "multi_compile _ C"});  // [A], [A C], [B], [B C]
    for (SelectionPolicy policy : {SelectionPolicy::Strict, SelectionPolicy::Exact}) {
        Selection selection = f.select({"C"}, policy);
        EXPECT_FALSE(selection.index.has_value()) << toString(policy);
        EXPECT_FALSE(selection.exact);
        EXPECT_EQ(selection.nearest, (std::vector<size_t>{1, 3, 0})) << toString(policy);
    }
}

TEST(VariantSelector, NearestListIsShortWhenFewVariantsExist) {
    Fixture f({"multi_compile A B"});
    Selection selection = f.select({}, SelectionPolicy::Strict);
    EXPECT_EQ(selection.nearest, (std::vector<size_t>{0, 1}));
}

TEST(VariantSelector, FullShadowsDirectionalSoftFallsBackToHardShadows) {
    Fixture f({"multi_compile_fwdadd_fullshadows"});
    Selection selection =
        f.select({"DIRECTIONAL", "SHADOWS_SCREEN", "SHADOWS_SOFT"}, SelectionPolicy::Closest);
    ASSERT_TRUE(selection.index);
    EXPECT_EQ(f.space.table().namesOf(f.variants[*selection.index]),
              (std::vector<std::string>{"DIRECTIONAL", "SHADOWS_SCREEN"}));
}

TEST(VariantSelector, NoVariantsMeansNoSelection) {
    for (SelectionPolicy policy : kAllPolicies) {
        Selection selection = selectVariant({}, VariantKey{}, policy);
        EXPECT_FALSE(selection.index.has_value());
        EXPECT_TRUE(selection.nearest.empty());
    }
}

TEST(VariantSelector, PolicyNamesRoundTrip) {
    for (SelectionPolicy policy : kAllPolicies) {
        EXPECT_EQ(parseSelectionPolicy(toString(policy)), policy);
    }
    EXPECT_EQ(parseSelectionPolicy("Closest"), std::nullopt);
    EXPECT_EQ(parseSelectionPolicy("nearest"), std::nullopt);
}

}  // namespace
}  // namespace varc::variants
