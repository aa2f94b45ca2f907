// SPDX-License-Identifier: Apache-2.0
// Strip rules: scope (shader glob, pass, stage) and what they remove, with hand-counted results.
#include <gtest/gtest.h>

#include "VariantsTestSupport.h"
#include "varc/variants/StripRules.h"

namespace varc::variants {
namespace {

using testing::parse;

struct Pass {
    PassKeywords keywords;
    std::optional<VariantSpace> space;
};

Pass passOf(const std::vector<std::string>& pragmas) {
    DiagnosticList sink;
    Pass pass;
    pass.keywords = *parse(pragmas, sink);
    pass.space = VariantSpace::build(pass.keywords, sink);
    EXPECT_TRUE(pass.space.has_value());
    EXPECT_TRUE(sink.diagnostics().empty()) << sink.diagnostics()[0].message;
    return pass;
}

// Applies |rules| to every variant of |pass|; returns the keys left and the per-rule counts.
std::pair<std::vector<VariantKey>, std::vector<uint64_t>> strip(const Pass& pass,
                                                                const std::vector<StripRule>& rules) {
    std::vector<PassStripRule> compiled;
    for (const StripRule& rule : rules) {
        compiled.push_back(compileStripRule(rule, pass.keywords, pass.space->table()));
    }
    std::vector<VariantKey> keys = pass.space->enumerate();
    std::vector<uint64_t> removed = applyStripRules(compiled, keys);
    return {keys, removed};
}

TEST(StripRules, GlobsMatchRunsAndLiterals) {
    EXPECT_TRUE(globMatches("Custom/*", "Custom/Water"));
    EXPECT_TRUE(globMatches("*", ""));
    EXPECT_TRUE(globMatches("a*b*c", "aXXbYbc"));
    EXPECT_FALSE(globMatches("a*b*c", "aXXbYbcd"));
    EXPECT_FALSE(globMatches("Custom/*", "Legacy/Water"));
    EXPECT_TRUE(globMatches("Custom/Water", "Custom/Water"));
    EXPECT_FALSE(globMatches("custom/water", "Custom/Water"));  // shader names are case-sensitive
}

TEST(StripRules, ScopeIsShaderPassNameOrLightMode) {
    StripRule rule;
    rule.shader = "Custom/*";
    rule.pass = "forwardadd";
    EXPECT_TRUE(stripRuleApplies(rule, "Custom/Water", "", "ForwardAdd"));
    EXPECT_TRUE(stripRuleApplies(rule, "Custom/Water", "FORWARDADD", "Always"));
    EXPECT_FALSE(stripRuleApplies(rule, "Custom/Water", "FORWARD", "ForwardBase"));
    EXPECT_FALSE(stripRuleApplies(rule, "Hidden/Blit", "", "ForwardAdd"));
    EXPECT_TRUE(stripRuleApplies(StripRule{}, "Any", "", ""));
}

TEST(StripRules, WithAndWithoutCountHandComputed) {
    // 3 fog options x 2 lightmap options = 6 variants.
    Pass pass = passOf({"multi_compile _ FOG_LINEAR FOG_EXP2",
                        "multi_compile _ LIGHTMAP_ON"});
    StripRule rule;
    rule.with = {"FOG_EXP2"};
    rule.without = {"LIGHTMAP_ON"};
    auto [keys, removed] = strip(pass, {rule});
    EXPECT_EQ(removed, (std::vector<uint64_t>{1}));  // only {FOG_EXP2}
    EXPECT_EQ(keys.size(), 5u);
}

TEST(StripRules, AVariantCountsForTheFirstRuleThatMatches) {
    Pass pass = passOf({"multi_compile _ A", "multi_compile _ B"});
    StripRule a, b;
    a.with = {"A"};  // {A}, {A B}
    b.with = {"B"};  // {B}, {A B} - but {A B} went to the first rule
    auto [keys, removed] = strip(pass, {a, b});
    EXPECT_EQ(removed, (std::vector<uint64_t>{2, 1}));
    ASSERT_EQ(keys.size(), 1u);
    EXPECT_TRUE(keys[0].empty());
}

TEST(StripRules, AnUndeclaredKeywordMakesWithNeverMatchAndWithoutAlwaysHold) {
    Pass pass = passOf({"multi_compile _ A"});
    StripRule absent;
    absent.with = {"A", "NOT_DECLARED"};
    StripRule loose;
    loose.with = {"A"};
    loose.without = {"NOT_DECLARED"};
    auto [keys, removed] = strip(pass, {absent, loose});
    EXPECT_EQ(removed, (std::vector<uint64_t>{0, 1}));
    EXPECT_EQ(keys.size(), 1u);
}

TEST(StripRules, AStageSeesOnlyItsOwnAndUnsuffixedSets) {
    // 2 x 2 = 4 variants; V is a vertex keyword, F a fragment one.
    Pass pass = passOf({"multi_compile_vertex _ V", "multi_compile_fragment _ F"});
    StripRule vertexF;
    vertexF.stage = Stage::Vertex;
    vertexF.with = {"F"};  // the vertex stage never sees F: removes nothing
    StripRule fragmentF = vertexF;
    fragmentF.stage = Stage::Fragment;
    auto [keys, removed] = strip(pass, {vertexF, fragmentF});
    EXPECT_EQ(removed, (std::vector<uint64_t>{0, 2}));  // {F}, {F V}
    EXPECT_EQ(keys.size(), 2u);
}

}  // namespace
}  // namespace varc::variants
