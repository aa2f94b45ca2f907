// SPDX-License-Identifier: Apache-2.0
// MaterialSelection: Unity's shader_feature rules per pass, with hand-computed counts.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "VariantsTestSupport.h"
#include "varc/core/JoinWords.h"
#include "varc/variants/MaterialSelection.h"

namespace varc::variants {
namespace {

using Listing = std::vector<std::string>;
using Materials = std::vector<std::vector<std::string>>;

std::vector<KeywordRequest> materials(const Materials& keywordLists) {
    std::vector<KeywordRequest> requests;
    for (size_t i = 0; i < keywordLists.size(); ++i) {
        requests.push_back({RequestKind::Material, "M" + std::to_string(i), keywordLists[i]});
    }
    return requests;
}

// Parses |pragmas| and selects for |requests|; fails the test on a parse error.
std::optional<MaterialSelection> selectionOf(const std::vector<std::string>& pragmas,
                                             std::vector<KeywordRequest> requests,
                                             bool alwaysIncluded = false) {
    DiagnosticList sink;
    std::optional<PassKeywords> keywords = testing::parse(pragmas, sink);
    EXPECT_TRUE(keywords.has_value()) << ::testing::PrintToString(pragmas);
    if (!keywords) return std::nullopt;
    std::optional<VariantSpace> space = VariantSpace::build(*keywords, sink);
    EXPECT_TRUE(space.has_value());
    if (!space) return std::nullopt;
    return MaterialSelection::select(*keywords, *space, std::move(requests), alwaysIncluded);
}

// The shipped variants in order, one sorted keyword line each ("" for none).
Listing shipped(const MaterialSelection& selection) {
    Listing lines;
    for (const VariantKey& key : selection.enumerate()) {
        lines.push_back(joinWords(selection.space().table().namesOf(key)));
    }
    return lines;
}

VariantKey keyOf(const MaterialSelection& selection, const Listing& names) {
    return selection.space().table().keyOf(names);
}

// Reference §2.3's worked example pass: 3 · 2 · 4 = 24 declared variants.
const std::vector<std::string> kWorkedExample = {"shader_feature _ _A _B",
                                                 "shader_feature_local _C", "multi_compile_fog"};

TEST(MaterialSelection, NoMaterialShipsTheAllOffFeatureCombination) {
    // multi_compile: 3 options all ship; `_ F` -> _, `G H` (no _) -> G: 3 · 1 · 1 = 3.
    auto selection =
        selectionOf({"multi_compile _ A B", "shader_feature F", "shader_feature G H"}, {});
    ASSERT_TRUE(selection);
    EXPECT_EQ(selection->counts().declared, 12u);  // 3 · 2 · 2
    EXPECT_EQ(selection->count(), 3u);
    EXPECT_EQ(shipped(*selection), (Listing{"G", "A G", "B G"}));
    VariantVerdict verdict = selection->explain(keyOf(*selection, {"A", "G"}));
    EXPECT_TRUE(verdict.ships);
    EXPECT_EQ(verdict.reason, VerdictReason::NoMaterialDefault);
    EXPECT_EQ(selection->explain(keyOf(*selection, {"F", "G"})).text,
              "no material uses the shader: only its all-off shader_feature combination ships");
}

TEST(MaterialSelection, OneMaterialShipsItsCombinationTimesMultiCompile) {
    // M0 -> (_A, _C); fog ships all 4: 1 · 4 = 4.
    auto selection = selectionOf(kWorkedExample, materials({{"_A", "_C"}}));
    ASSERT_TRUE(selection);
    EXPECT_EQ(selection->counts().full, 24u);
    EXPECT_EQ(selection->counts().declared, 24u);
    EXPECT_EQ(selection->count(), 4u);
    EXPECT_EQ(shipped(*selection),
              (Listing{"_A _C", "FOG_LINEAR _A _C", "FOG_EXP _A _C", "FOG_EXP2 _A _C"}));
}

TEST(MaterialSelection, WorkedExampleOfTheReference) {
    // M0 -> (_A,_C), M1 -> (_,_), M2 -> (_A,_) (2+ in a set: first declared): 3 · 4 = 12.
    auto selection =
        selectionOf(kWorkedExample, materials({{"_A", "_C", "JUNK"}, {}, {"_A", "_B"}}));
    ASSERT_TRUE(selection);
    EXPECT_EQ(selection->count(), 12u);
    EXPECT_EQ(selection->combinations().size(), 3u);
}

TEST(MaterialSelection, DuplicateProjectionsShipOnce) {
    // All three project to (_A, _): one combination · 4 fog = 4.
    auto selection = selectionOf(kWorkedExample,
                                 materials({{"_A"}, {"JUNK", "_A"}, {"FOG_LINEAR", "_A", "_A"}}));
    ASSERT_TRUE(selection);
    EXPECT_EQ(selection->count(), 4u);
    ASSERT_EQ(selection->combinations().size(), 1u);
    VariantVerdict verdict = selection->explain(keyOf(*selection, {"_A", "FOG_EXP"}));
    EXPECT_EQ(verdict.reason, VerdictReason::Requested);
    EXPECT_EQ(verdict.requests, (std::vector<size_t>{0, 1, 2}));
    EXPECT_EQ(verdict.text, "enabled by material 'M0', material 'M1', material 'M2'");
}

TEST(MaterialSelection, UndeclaredAndMultiCompileKeywordsAreIgnoredAndReported) {
    // JUNK undeclared, FOG_EXP is multi_compile: M0 -> (_, _C): 1 · 4 = 4.
    auto selection = selectionOf(kWorkedExample, materials({{"JUNK", "FOG_EXP", "_C"}}));
    ASSERT_TRUE(selection);
    EXPECT_EQ(selection->count(), 4u);
    const RequestProjection& projection = selection->projections()[0];
    EXPECT_EQ(projection.undeclared, (Listing{"JUNK"}));
    EXPECT_EQ(projection.multiCompile, (Listing{"FOG_EXP"}));
    EXPECT_EQ(projection.key, keyOf(*selection, {"_C"}));
    EXPECT_EQ(projection.options, (std::vector<size_t>{0, 1}));
}

TEST(MaterialSelection, SetWithoutUnderscoreDefaultsToItsFirstKeyword) {
    // M0 none on -> RED (defaulted), M1 -> BLUE: 2 combinations · 1 = 2.
    auto selection = selectionOf({"shader_feature RED GREEN BLUE"}, materials({{}, {"BLUE"}}));
    ASSERT_TRUE(selection);
    EXPECT_EQ(selection->count(), 2u);
    EXPECT_EQ(shipped(*selection), (Listing{"RED", "BLUE"}));
    EXPECT_EQ(selection->projections()[0].defaultedSets, (std::vector<size_t>{0}));
    EXPECT_TRUE(selection->projections()[1].defaultedSets.empty());
    EXPECT_EQ(selection->explain(keyOf(*selection, {"GREEN"})).text, "no material enables GREEN");
}

TEST(MaterialSelection, TwoKeywordsOfOneSetKeepTheFirstDeclared) {
    // {_B, _A} on `_ _A _B` -> _A (declared first), _B dropped: 1 · 4 = 4.
    auto selection = selectionOf(kWorkedExample, materials({{"_B", "_A"}}));
    ASSERT_TRUE(selection);
    EXPECT_EQ(selection->count(), 4u);
    ASSERT_EQ(selection->projections()[0].conflicts.size(), 1u);
    const FeatureConflict& conflict = selection->projections()[0].conflicts[0];
    EXPECT_EQ(conflict.set, 0u);
    EXPECT_EQ(conflict.kept, "_A");
    EXPECT_EQ(conflict.dropped, (Listing{"_B"}));
}

TEST(MaterialSelection, LocalAndStageSuffixedFeatureSetsFollowTheSameRule) {
    // (A,_) and (_,B) ship, M's 2 options all: 2 · 2 = 4 of 2 · 2 · 2 = 8.
    auto selection = selectionOf({"shader_feature_local_fragment _ A", "shader_feature_vertex B",
                                  "multi_compile_local_fragment _ M"},
                                 materials({{"A"}, {"B", "M"}}));
    ASSERT_TRUE(selection);
    EXPECT_EQ(selection->counts().declared, 8u);
    EXPECT_EQ(selection->count(), 4u);
    EXPECT_EQ(shipped(*selection), (Listing{"B", "B M", "A", "A M"}));
}

TEST(MaterialSelection, ShortcutSetsShipWhollyWithTheirValidityRules) {
    // fwdadd_fullshadows keeps 13 of 40; one combination (_A): 13 · 1 = 13 of 13 · 3 = 39.
    auto selection = selectionOf({"multi_compile_fwdadd_fullshadows", "shader_feature _ _A _B"},
                                 materials({{"_A", "SPOT"}}));
    ASSERT_TRUE(selection);
    EXPECT_EQ(selection->counts().full, 120u);  // 2 · 4 · 5 · 3
    EXPECT_EQ(selection->counts().declared, 39u);
    EXPECT_EQ(selection->count(), 13u);
    EXPECT_EQ(selection->enumerate().size(), 13u);
    VariantVerdict invalid =
        selection->explain(keyOf(*selection, {"POINT", "SHADOWS_DEPTH", "_A"}));
    EXPECT_FALSE(invalid.ships);
    EXPECT_EQ(invalid.reason, VerdictReason::NotDeclared);
    EXPECT_EQ(invalid.text, "a shortcut's validity rule excludes it");
}

TEST(MaterialSelection, SkippedKeywordsAreIgnoredLikeUndeclaredOnes) {
    // MC {_, A, C} (B skipped) = 3; M0 {G} -> G skipped -> _; M1 -> F: 2 · 3 = 6 of 3 · 3 = 9.
    auto selection =
        selectionOf({"multi_compile _ A B C", "shader_feature _ F G H", "skip_variants B G"},
                    materials({{"G"}, {"F"}}));
    ASSERT_TRUE(selection);
    EXPECT_EQ(selection->counts().full, 16u);
    EXPECT_EQ(selection->counts().declared, 9u);
    EXPECT_EQ(selection->count(), 6u);
    EXPECT_EQ(selection->projections()[0].skipped, (Listing{"G"}));
    EXPECT_EQ(shipped(*selection), (Listing{"", "F", "A", "A F", "C", "C F"}));
}

TEST(MaterialSelection, FeatureSetWithEverythingSkippedShipsNothing) {
    // Both options of `A B` skipped: the space is empty, so 0.
    auto selection = selectionOf({"shader_feature A B", "multi_compile _ M", "skip_variants A B"},
                                 materials({{"A"}}));
    ASSERT_TRUE(selection);
    EXPECT_EQ(selection->count(), 0u);
    EXPECT_TRUE(selection->enumerate().empty());
}

TEST(MaterialSelection, AlwaysIncludedShipsEveryDeclaredVariant) {
    // shader_feature counted like multi_compile: 3 · 2 · 4 = 24 whatever the materials.
    auto selection = selectionOf(kWorkedExample, materials({{"_A"}}), true);
    ASSERT_TRUE(selection);
    EXPECT_EQ(selection->count(), 24u);
    EXPECT_EQ(selection->enumerate().size(), 24u);
    VariantVerdict verdict = selection->explain(keyOf(*selection, {"_B", "_C"}));
    EXPECT_TRUE(verdict.ships);
    EXPECT_EQ(verdict.reason, VerdictReason::AlwaysIncluded);
}

TEST(MaterialSelection, PassWithoutFeatureSetsShipsItsWholeSpace) {
    // multi_compile only: 3 · 2 = 6 with or without materials.
    auto selection =
        selectionOf({"multi_compile _ A B", "multi_compile _ C"}, materials({{"A"}, {"JUNK"}}));
    ASSERT_TRUE(selection);
    EXPECT_EQ(selection->count(), 6u);
    EXPECT_EQ(shipped(*selection), (Listing{"", "C", "A", "A C", "B", "B C"}));
}

TEST(MaterialSelection, ProjectionIsPerPass) {
    // The caster declares neither _NORMALMAP nor _EMISSION: all 3 materials -> (_): 1 · 2 = 2;
    // the forward pass sees 3 combinations · 4 fog = 12.
    Materials used = {{"_NORMALMAP"}, {"_EMISSION", "_NORMALMAP"}, {}};
    auto forward =
        selectionOf({"shader_feature _NORMALMAP", "shader_feature _EMISSION", "multi_compile_fog"},
                    materials(used));
    auto caster = selectionOf({"multi_compile_shadowcaster", "shader_feature _ALPHATEST_ON"},
                              materials(used));
    ASSERT_TRUE(forward && caster);
    EXPECT_EQ(forward->count(), 12u);
    EXPECT_EQ(caster->count(), 2u);
    EXPECT_EQ(caster->projections()[1].undeclared, (Listing{"_EMISSION", "_NORMALMAP"}));
}

TEST(MaterialSelection, DynamicBranchKeywordsMakeNoVariants) {
    // D is dynamic_branch: M0 -> (_): 1 · 2 (M) = 2.
    auto selection = selectionOf({"dynamic_branch D", "shader_feature _ F", "multi_compile _ M"},
                                 materials({{"D"}}));
    ASSERT_TRUE(selection);
    EXPECT_EQ(selection->count(), 2u);
    EXPECT_EQ(selection->projections()[0].dynamicBranch, (Listing{"D"}));
    EXPECT_TRUE(selection->projections()[0].undeclared.empty());
}

TEST(MaterialSelection, CollectionVariantProjectsLikeAMaterial) {
    // No material: the all-off (_,_) ships, plus the entry's (_B,_); DIRECTIONAL is not
    // declared, FOG_EXP is multi_compile (no effect): 2 · 4 = 8.
    auto selection = selectionOf(
        kWorkedExample,
        {{RequestKind::CollectionVariant, "Warmup[0]", {"DIRECTIONAL", "FOG_EXP", "_B"}}});
    ASSERT_TRUE(selection);
    EXPECT_EQ(selection->count(), 8u);
    EXPECT_EQ(selection->projections()[0].multiCompile, (Listing{"FOG_EXP"}));
    EXPECT_EQ(selection->projections()[0].undeclared, (Listing{"DIRECTIONAL"}));
    EXPECT_EQ(selection->explain(keyOf(*selection, {"_B"})).text,
              "enabled by collection variant 'Warmup[0]'");
    EXPECT_EQ(selection->explain(keyOf(*selection, {})).reason, VerdictReason::NoMaterialDefault);
}

TEST(MaterialSelection, CollectionVariantBesideAMaterialAddsOnlyItsCombination) {
    // A material exists, so no all-off default: (_A,_C) and (_B,_): 2 · 4 = 8.
    std::vector<KeywordRequest> requests = materials({{"_A", "_C"}});
    requests.push_back({RequestKind::CollectionVariant, "Warmup[0]", {"_B"}});
    auto selection = selectionOf(kWorkedExample, requests);
    ASSERT_TRUE(selection);
    EXPECT_EQ(selection->count(), 8u);
    EXPECT_FALSE(selection->explain(keyOf(*selection, {})).ships);
    EXPECT_EQ(selection->explain(keyOf(*selection, {"_C"})).text,
              "every material or collection variant enables one of _A _B");
    EXPECT_EQ(selection->explain(keyOf(*selection, {"_B", "_C"})).text,
              "no single material or collection variant has this shader_feature combination "
              "(_B _C)");
}

TEST(MaterialSelection, ExplainNamesWhatNoMaterialEnables) {
    // M0 -> (_A, _), M1 -> (_B, _C).
    auto selection =
        selectionOf({"shader_feature _ _A _B", "shader_feature _ _C", "shader_feature _ _DETAIL"},
                    materials({{"_A"}, {"_B", "_C"}}));
    ASSERT_TRUE(selection);
    EXPECT_EQ(selection->count(), 2u);
    EXPECT_EQ(selection->explain(keyOf(*selection, {"_A", "_DETAIL"})).text,
              "no material enables _DETAIL");
    EXPECT_EQ(selection->explain(keyOf(*selection, {"_C"})).text,
              "every material enables one of _A _B");
    EXPECT_EQ(selection->explain(keyOf(*selection, {"_A", "_C"})).text,
              "no single material has this shader_feature combination (_A _C)");
    VariantKey twoOfOneSet = keyOf(*selection, {"_A", "_B"});
    EXPECT_EQ(selection->explain(twoOfOneSet).reason, VerdictReason::NotDeclared);
    EXPECT_EQ(selection->explain(twoOfOneSet).text,
              "not a variant of this pass: its keywords are not one option of every set");
}

// Sets interleaved so pinned and free sets alternate: the full order must survive.
const std::vector<std::string> kInterleaved = {"shader_feature _ A B", "multi_compile _ M N",
                                               "shader_feature _ C", "multi_compile X Y"};

TEST(MaterialSelection, OrderIsTheFullSpaceOrderFiltered) {
    // Combinations (B,_), (A,C), (_,C) · 3 · 2 = 18 of 3 · 3 · 2 · 2 = 36.
    auto selection = selectionOf(kInterleaved, materials({{"B"}, {"A", "C"}, {"C"}}));
    ASSERT_TRUE(selection);
    const KeywordTable& table = selection->space().table();
    std::set<VariantKey> allowed = {table.keyOf({"B"}), table.keyOf({"A", "C"}),
                                    table.keyOf({"C"})};
    VariantKey featureMask = table.keyOf({"A", "B", "C"});
    std::vector<VariantKey> expected;
    for (const VariantKey& key : selection->space().enumerate()) {
        if (allowed.count(key & featureMask) != 0) expected.push_back(key);
    }
    EXPECT_EQ(expected.size(), 18u);
    EXPECT_EQ(selection->count(), 18u);
    EXPECT_EQ(selection->enumerate(), expected);
}

TEST(MaterialSelection, MaterialOrderDoesNotMatter) {
    Materials used = {{"B"}, {"A", "C"}, {"C"}, {"JUNK"}};
    auto first = selectionOf(kInterleaved, materials(used));
    std::reverse(used.begin(), used.end());
    auto second = selectionOf(kInterleaved, materials(used));
    ASSERT_TRUE(first && second);
    EXPECT_EQ(first->enumerate(), second->enumerate());
    EXPECT_EQ(first->combinations(), second->combinations());
}

TEST(MaterialSelection, TrillionVariantPassWithFiveMaterialsIsPlannedWithoutEnumerating) {
    // 40 `_ K` feature sets · fog 4 · `_ M` 2 = 2^43 declared (8.8e12);
    // 6 materials, the last a reordered duplicate: 5 combinations · 4 · 2 = 40 ship.
    std::vector<std::string> pragmas = {"multi_compile_fog"};
    for (int i = 0; i < 40; ++i) {
        pragmas.push_back("shader_feature _ K" + std::string(i < 10 ? "0" : "") +
                          std::to_string(i));
    }
    pragmas.push_back("multi_compile _ M");
    Materials used = {{"K00"}, {"K39", "K05"}, {}, {"K17", "K18", "K19"}, {"K39"}, {"K05", "K39"}};
    auto selection = selectionOf(pragmas, materials(used));
    ASSERT_TRUE(selection);
    EXPECT_EQ(selection->counts().declared, uint64_t{1} << 43);
    EXPECT_EQ(selection->count(), 40u);
    std::vector<VariantKey> keys = selection->enumerate();
    std::set<VariantKey> expected;
    const KeywordTable& table = selection->space().table();
    for (const std::vector<std::string>& material : used) {
        for (std::string fog : {"", "FOG_LINEAR", "FOG_EXP", "FOG_EXP2"}) {
            for (std::string m : {"", "M"}) {
                std::vector<std::string> names = material;
                names.push_back(fog);
                names.push_back(m);
                expected.insert(table.keyOf(names));
            }
        }
    }
    EXPECT_EQ(std::set<VariantKey>(keys.begin(), keys.end()), expected);
    EXPECT_EQ(keys.size(), 40u);
    // Fog is declared first, so it varies slowest: the first 10 keys have fog off.
    for (size_t i = 0; i < 10; ++i) EXPECT_EQ(keys[i] & table.keyOf({"FOG_LINEAR"}), VariantKey{});
    for (const VariantKey& key : keys) EXPECT_TRUE(selection->explain(key).ships);
    EXPECT_EQ(selection->explain(table.keyOf({"K01"})).text, "no material enables K01");
}

}  // namespace
}  // namespace varc::variants
