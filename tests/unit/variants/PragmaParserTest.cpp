// SPDX-License-Identifier: Apache-2.0
// parsePragmas: directive forms, underscore rules, errors with columns, other pragmas.
#include <gtest/gtest.h>

#include <algorithm>

#include "VariantsTestSupport.h"
#include "varc/variants/PragmaParser.h"

namespace varc::variants {
namespace {

using testing::messages;
using testing::parse;
using testing::pragmaLines;
using Keywords = std::vector<std::string>;

PassKeywords parseOk(const std::vector<std::string>& texts) {
    DiagnosticList sink;
    std::optional<PassKeywords> keywords = parse(texts, sink);
    EXPECT_TRUE(keywords.has_value());
    EXPECT_FALSE(sink.hasErrors());
    return keywords.value_or(PassKeywords{});
}

// The single error |texts| produce; fails the test if there is not exactly one.
Diagnostic parseError(const std::vector<std::string>& texts, uint32_t hashColumn = 1) {
    DiagnosticList sink;
    std::optional<PassKeywords> keywords = parsePragmas(pragmaLines(texts, hashColumn), sink);
    EXPECT_FALSE(keywords.has_value());
    EXPECT_EQ(sink.errorCount(), 1u);
    for (const Diagnostic& diagnostic : sink.diagnostics()) {
        if (diagnostic.severity == Severity::Error) return diagnostic;
    }
    return {};
}

TEST(PragmaParser, PlainMultiCompileIsOneSet) {
    PassKeywords kw = parseOk({"multi_compile _ A B"});
    ASSERT_EQ(kw.sets.size(), 1u);
    EXPECT_EQ(kw.sets[0].kind, DirectiveKind::MultiCompile);
    EXPECT_FALSE(kw.sets[0].local);
    EXPECT_EQ(kw.sets[0].stages, kEverySetStage);
    EXPECT_EQ(kw.sets[0].keywords, (Keywords{"", "A", "B"}));
    EXPECT_EQ(kw.sets[0].directive, "multi_compile");
    EXPECT_EQ(kw.sets[0].location, (SourceLocation{7, 1, 1}));
}

TEST(PragmaParser, LocalAndStageSuffixesCombine) {
    PassKeywords kw = parseOk({"multi_compile_local_fragment _ A", "shader_feature_local_vertex B",
                               "multi_compile_vertex C D", "shader_feature_local E"});
    ASSERT_EQ(kw.sets.size(), 4u);
    EXPECT_TRUE(kw.sets[0].local);
    EXPECT_EQ(kw.sets[0].stages, stageBit(Stage::Fragment));
    EXPECT_EQ(kw.sets[0].directive, "multi_compile_local_fragment");
    EXPECT_EQ(kw.sets[1].kind, DirectiveKind::ShaderFeature);
    EXPECT_TRUE(kw.sets[1].local);
    EXPECT_EQ(kw.sets[1].stages, stageBit(Stage::Vertex));
    EXPECT_FALSE(kw.sets[2].local);
    EXPECT_EQ(kw.sets[2].stages, stageBit(Stage::Vertex));
    EXPECT_TRUE(kw.sets[3].local);
    EXPECT_EQ(kw.sets[3].stages, kEverySetStage);
}

TEST(PragmaParser, EveryStageSuffixMapsToItsBit) {
    const std::pair<const char*, uint32_t> cases[] = {
        {"vertex", stageBit(Stage::Vertex)},     {"fragment", stageBit(Stage::Fragment)},
        {"hull", stageBit(Stage::Hull)},         {"domain", stageBit(Stage::Domain)},
        {"geometry", stageBit(Stage::Geometry)}, {"raytracing", kRaytracingStages}};
    for (const auto& [suffix, bit] : cases) {
        PassKeywords kw = parseOk({std::string("multi_compile_") + suffix + " _ A"});
        ASSERT_EQ(kw.sets.size(), 1u) << suffix;
        EXPECT_EQ(kw.sets[0].stages, bit) << suffix;
    }
}

TEST(PragmaParser, ShaderFeatureSingleKeywordImpliesOff) {
    PassKeywords kw = parseOk({"shader_feature FANCY", "shader_feature RED GREEN"});
    EXPECT_EQ(kw.sets[0].keywords, (Keywords{"", "FANCY"}));
    EXPECT_EQ(kw.sets[1].keywords, (Keywords{"RED", "GREEN"}));
}

TEST(PragmaParser, MultiCompileSingleKeywordIsAlwaysOn) {
    PassKeywords kw = parseOk({"multi_compile ALWAYS"});
    EXPECT_EQ(kw.sets[0].keywords, (Keywords{"ALWAYS"}));
}

TEST(PragmaParser, AllUnderscoreNamesAreTheNoKeywordEntry) {
    PassKeywords kw = parseOk({"multi_compile ___ UNITY_HDR_ON", "multi_compile A __"});
    EXPECT_EQ(kw.sets[0].keywords, (Keywords{"", "UNITY_HDR_ON"}));
    EXPECT_EQ(kw.sets[1].keywords, (Keywords{"A", ""}));
}

TEST(PragmaParser, SeveralUnderscoreEntriesInOneSetIsAnError) {
    Diagnostic error = parseError({"multi_compile _ __ A"});
    EXPECT_NE(error.message.find("no-keyword entry"), std::string::npos) << error.message;
    EXPECT_EQ(error.location.column, 25u);
}

TEST(PragmaParser, KeywordRepeatedInSetPointsAtSecondOccurrence) {
    // Same line as tests/cli/cases/error-duplicate-keyword: '#' at column 13.
    Diagnostic error = parseError({"multi_compile _ FOG_ON LIGHT_ON FOG_ON"}, 13);
    EXPECT_EQ(error.location, (SourceLocation{7, 1, 53}));
    EXPECT_NE(error.message.find("'FOG_ON'"), std::string::npos);
    ASSERT_EQ(error.notes.size(), 1u);
    EXPECT_EQ(error.notes[0].location.column, 37u);
}

// Unity merges a set written again exactly: the count does not change.
TEST(PragmaParser, AUserSetIdenticalToAShortcutSetIsMergedWithANote) {
    DiagnosticList sink;
    std::optional<PassKeywords> merged =
        parse({"multi_compile_fwdbase", "multi_compile _ VERTEXLIGHT_ON"}, sink);
    ASSERT_TRUE(merged.has_value());
    EXPECT_FALSE(sink.hasErrors());
    ASSERT_EQ(messages(sink, Severity::Note).size(), 1u);
    EXPECT_NE(messages(sink, Severity::Note)[0].find("merged"), std::string::npos);
    PassKeywords alone = parseOk({"multi_compile_fwdbase"});
    ASSERT_EQ(merged->sets.size(), alone.sets.size());
    for (size_t i = 0; i < alone.sets.size(); ++i) {
        EXPECT_EQ(merged->sets[i].keywords, alone.sets[i].keywords);
    }
}

TEST(PragmaParser, IdenticalUserSetsInAnyOrderAreMerged) {
    DiagnosticList sink;
    std::optional<PassKeywords> kw = parse({"multi_compile ___ A B", "multi_compile B _ A"}, sink);
    ASSERT_TRUE(kw.has_value());
    ASSERT_EQ(kw->sets.size(), 1u);
    EXPECT_EQ(kw->sets[0].keywords, (Keywords{"", "A", "B"}));
}

TEST(PragmaParser, ASemicolonAfterTheLastKeywordIsIgnoredWithAWarning) {
    DiagnosticList sink;
    std::optional<PassKeywords> kw = parse({"multi_compile TEST_1 TEST_2;"}, sink);
    ASSERT_TRUE(kw.has_value());
    ASSERT_EQ(kw->sets.size(), 1u);
    EXPECT_EQ(kw->sets[0].keywords, (Keywords{"TEST_1", "TEST_2"}));
    ASSERT_EQ(messages(sink, Severity::Warning).size(), 1u);
    EXPECT_NE(messages(sink, Severity::Warning)[0].find("';' after keyword 'TEST_2'"),
              std::string::npos);
    DiagnosticList bad;
    EXPECT_FALSE(parse({"multi_compile A ;"}, bad).has_value());
}

TEST(PragmaParser, RepeatedSetInAnyOrderIsAnError) {
    Diagnostic error = parseError({"multi_compile A B", "shader_feature B A"});
    EXPECT_NE(error.message.find("duplicate keyword set"), std::string::npos) << error.message;
    EXPECT_NE(error.message.find("line 1"), std::string::npos) << error.message;
    EXPECT_EQ(error.location, (SourceLocation{7, 2, 9}));
    ASSERT_EQ(error.notes.size(), 1u);
    EXPECT_EQ(error.notes[0].location, (SourceLocation{7, 1, 9}));
}

TEST(PragmaParser, KeywordInTwoSetsNamesTheFirstDeclaration) {
    Diagnostic error = parseError({"multi_compile _ A", "multi_compile B A"});
    EXPECT_NE(error.message.find("'A'"), std::string::npos);
    EXPECT_NE(error.message.find("line 1, column 25"), std::string::npos) << error.message;
    EXPECT_EQ(error.location, (SourceLocation{7, 2, 25}));
    ASSERT_EQ(error.notes.size(), 1u);
    EXPECT_EQ(error.notes[0].location, (SourceLocation{7, 1, 25}));
}

TEST(PragmaParser, UserSetSharingAShortcutKeywordIsAnError) {
    Diagnostic error = parseError({"multi_compile_fwdadd", "multi_compile _ SPOT_X SPOT"});
    EXPECT_NE(error.message.find("'SPOT'"), std::string::npos);
    EXPECT_EQ(error.location.column, 32u);
}

// Unity ignores a shortcut it does not know (shaders with `multi_compile_fwdbadd` compile there):
// a warning with the suggestion, and the pragma declares nothing.
TEST(PragmaParser, UnknownShortcutIsIgnoredWithAWarningThatSuggestsTheClosestName) {
    DiagnosticList sink;
    std::optional<PassKeywords> kw =
        parsePragmas(pragmaLines({"multi_compile_fwdadd_fullshadow", "multi_compile _ A"}, 13), sink);
    ASSERT_TRUE(kw.has_value());
    EXPECT_FALSE(sink.hasErrors());
    ASSERT_EQ(kw->sets.size(), 1u);
    EXPECT_EQ(kw->sets[0].keywords, (Keywords{"", "A"}));
    std::vector<Diagnostic> warnings;
    for (const Diagnostic& d : sink.diagnostics())
        if (d.severity == Severity::Warning) warnings.push_back(d);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0].location.column, 21u);
    EXPECT_NE(warnings[0].message.find("is ignored"), std::string::npos) << warnings[0].message;
    EXPECT_NE(warnings[0].message.find("did you mean 'multi_compile_fwdadd_fullshadows'?"),
              std::string::npos)
        << warnings[0].message;
}

TEST(PragmaParser, UnknownShortcutFarFromEverythingHasNoSuggestion) {
    DiagnosticList sink;
    ASSERT_TRUE(parse({"multi_compile_zzzzzzzzzzzz"}, sink).has_value());
    std::vector<std::string> warnings = messages(sink, Severity::Warning);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("unknown multi_compile shortcut"), std::string::npos);
    EXPECT_EQ(warnings[0].find("did you mean"), std::string::npos) << warnings[0];
}

TEST(PragmaParser, UnknownShortcutWithOnlyShortcutOptionsIsIgnored) {
    DiagnosticList sink;
    std::optional<PassKeywords> kw = parse({"multi_compile_fwdbadd nolightmap"}, sink);
    ASSERT_TRUE(kw.has_value());
    EXPECT_TRUE(kw->sets.empty());
    EXPECT_EQ(messages(sink, Severity::Warning).size(), 1u);
}

// Keywords after a misspelt directive are keywords the user wants: dropping them silently would
// lose variants, so this stays an error.
TEST(PragmaParser, MisspelledSuffixFormSuggestsTheSuffixForm) {
    Diagnostic error = parseError({"multi_compile_fragmnt _ A"});
    EXPECT_NE(error.message.find("did you mean 'multi_compile_fragment'?"), std::string::npos)
        << error.message;
}

TEST(PragmaParser, UnknownShaderFeatureSuffixIsAnError) {
    Diagnostic error = parseError({"shader_feature_locl A"});
    EXPECT_NE(error.message.find("did you mean 'shader_feature_local'?"), std::string::npos)
        << error.message;
}

TEST(PragmaParser, UnknownShortcutOptionWarnsWithTheClosestOption) {
    DiagnosticList sink;
    std::optional<PassKeywords> kw = parse({"multi_compile_fwdbase nolightmaps"}, sink);
    ASSERT_TRUE(kw.has_value());
    ASSERT_EQ(sink.diagnostics().size(), 1u);
    const Diagnostic& warning = sink.diagnostics()[0];
    EXPECT_EQ(warning.severity, Severity::Warning);
    EXPECT_EQ(warning.location.column, 31u);
    EXPECT_NE(warning.message.find("did you mean 'nolightmap'?"), std::string::npos)
        << warning.message;
}

TEST(PragmaParser, OptionWithoutEffectOnTheShortcutWarns) {
    DiagnosticList sink;
    std::optional<PassKeywords> kw = parse({"multi_compile_fog novertexlight"}, sink);
    ASSERT_TRUE(kw.has_value());
    ASSERT_EQ(messages(sink, Severity::Warning).size(), 1u);
    EXPECT_NE(messages(sink, Severity::Warning)[0].find("no effect"), std::string::npos);
    EXPECT_EQ(kw->sets.size(), 1u);
}

TEST(PragmaParser, InvalidKeywordNameIsAnError) {
    Diagnostic error = parseError({"multi_compile _ GOOD 3BAD"});
    EXPECT_NE(error.message.find("'3BAD'"), std::string::npos);
    EXPECT_EQ(error.location.column, 30u);
    EXPECT_EQ(parseError({"shader_feature A-B"}).location.column, 24u);
}

TEST(PragmaParser, EmptyKeywordDirectiveIsAnError) {
    EXPECT_NE(parseError({"multi_compile"}).message.find("declares no keywords"),
              std::string::npos);
    EXPECT_NE(parseError({"shader_feature_local"}).message.find("declares no keywords"),
              std::string::npos);
}

TEST(PragmaParser, DynamicBranchIsRecordedWithoutVariants) {
    PassKeywords kw = parseOk({"dynamic_branch FAST", "dynamic_branch_local _ X Y"});
    EXPECT_TRUE(kw.sets.empty());
    ASSERT_EQ(kw.dynamicBranches.size(), 2u);
    EXPECT_EQ(kw.dynamicBranches[0].kind, DirectiveKind::DynamicBranch);
    EXPECT_EQ(kw.dynamicBranches[0].keywords, (Keywords{"", "FAST"}));
    EXPECT_TRUE(kw.dynamicBranches[1].local);
}

TEST(PragmaParser, DynamicBranchWinsOverMultiCompileWithAWarning) {
    DiagnosticList sink;
    std::optional<PassKeywords> kw =
        parse({"multi_compile _ A B", "shader_feature C", "dynamic_branch A C"}, sink);
    ASSERT_TRUE(kw.has_value());
    EXPECT_EQ(messages(sink, Severity::Warning).size(), 2u);
    ASSERT_EQ(kw->sets.size(), 1u);  // `shader_feature C` has nothing left and is dropped
    EXPECT_EQ(kw->sets[0].keywords, (Keywords{"", "B"}));
    EXPECT_EQ(kw->dynamicBranches.size(), 1u);
    EXPECT_EQ(sink.diagnostics()[0].notes.size(), 1u);
}

TEST(PragmaParser, DynamicBranchRejectsStageSuffixes) {
    EXPECT_NE(parseError({"dynamic_branch_fragment A"}).message.find("no stage suffix"),
              std::string::npos);
}

TEST(PragmaParser, SkipVariantsIsCollectedFromAnyPosition) {
    PassKeywords kw = parseOk({"skip_variants A", "multi_compile _ A B", "skip_variants C D"});
    EXPECT_EQ(kw.skipped, (Keywords{"A", "C", "D"}));
    EXPECT_NE(parseError({"skip_variants _"}).message.find("invalid keyword"), std::string::npos);
}

TEST(PragmaParser, EntryPointsTargetRenderersInstancingAndOthers) {
    PassKeywords kw = parseOk({"vertex vert", "fragment frag", "geometry geom", "hull hs",
                               "domain ds", "target 4.5", "exclude_renderers gles d3d9",
                               "only_renderers vulkan", "instancing_options assumeuniformscaling",
                               "enable_d3d11_debug_symbols", "surface surf Standard"});
    EXPECT_EQ(kw.vertexEntry, "vert");
    EXPECT_EQ(kw.fragmentEntry, "frag");
    EXPECT_EQ(kw.geometryEntry, "geom");
    EXPECT_EQ(kw.hullEntry, "hs");
    EXPECT_EQ(kw.domainEntry, "ds");
    EXPECT_EQ(kw.target, "4.5");
    EXPECT_EQ(kw.excludeRenderers, (Keywords{"gles", "d3d9"}));
    EXPECT_EQ(kw.onlyRenderers, (Keywords{"vulkan"}));
    EXPECT_EQ(kw.instancingOptions, (Keywords{"assumeuniformscaling"}));
    EXPECT_EQ(kw.otherPragmas, (Keywords{"enable_d3d11_debug_symbols", "surface surf Standard"}));
    EXPECT_TRUE(kw.sets.empty());
}

TEST(PragmaParser, ConflictingEntryPointsAreAnError) {
    Diagnostic error = parseError({"vertex a", "vertex b"});
    EXPECT_EQ(error.location, (SourceLocation{7, 2, 16}));
    EXPECT_TRUE(parseOk({"vertex a", "vertex a"}).vertexEntry == "a");
    EXPECT_NE(parseError({"fragment"}).message.find("needs a function name"), std::string::npos);
}

TEST(PragmaParser, ShortcutSetsCarryDirectiveAndPragmaLocation) {
    PassKeywords kw = parseOk({"target 3.0", "multi_compile_fwdadd_fullshadows"});
    ASSERT_EQ(kw.sets.size(), 3u);
    for (const KeywordSetDecl& set : kw.sets) {
        EXPECT_EQ(set.directive, "multi_compile_fwdadd_fullshadows");
        EXPECT_EQ(set.location, (SourceLocation{7, 2, 1}));
        EXPECT_EQ(set.kind, DirectiveKind::MultiCompile);
    }
    EXPECT_EQ(kw.sets[0].keywords, (Keywords{"", "SHADOWS_SOFT"}));
    ASSERT_EQ(kw.rules.size(), 4u);
    EXPECT_EQ(kw.rules[0].origin, "multi_compile_fwdadd_fullshadows");
}

// Unity compiles a shortcut written twice as if written once; varc warns.
TEST(PragmaParser, AShortcutDeclaredTwiceCountsOnceWithAWarning) {
    DiagnosticList sink;
    std::optional<PassKeywords> twice = parse({"multi_compile_fwdbase", "multi_compile_fwdbase"}, sink);
    ASSERT_TRUE(twice.has_value());
    std::vector<std::string> warnings = messages(sink, Severity::Warning);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("declared twice"), std::string::npos) << warnings[0];
    PassKeywords once = parseOk({"multi_compile_fwdbase"});
    ASSERT_EQ(twice->sets.size(), once.sets.size());
    EXPECT_EQ(twice->rules.size(), once.rules.size());
}

// `multi_compile_fwdadd fullshadows`: Unity ignores the word; varc too, with a warning that
// names the shortcut the user probably meant.
TEST(PragmaParser, AnUnknownWordAfterAShortcutIsIgnoredWithAWarning) {
    DiagnosticList sink;
    std::optional<PassKeywords> kw = parse({"multi_compile_fwdadd fullshadows"}, sink);
    ASSERT_TRUE(kw.has_value());
    std::vector<std::string> warnings = messages(sink, Severity::Warning);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("'multi_compile_fwdadd_fullshadows'"), std::string::npos)
        << warnings[0];
    PassKeywords plain = parseOk({"multi_compile_fwdadd"});
    ASSERT_EQ(kw->sets.size(), plain.sets.size());
    EXPECT_EQ(kw->sets[0].keywords, plain.sets[0].keywords);
}

// Unity ignores stage suffixes on Vulkan: a suffixed copy of a shortcut's set is the same set,
// merged, and then defined in the stages of both.
TEST(PragmaParser, AStageSuffixedCopyOfAShortcutSetIsMerged) {
    DiagnosticList sink;
    std::optional<PassKeywords> kw =
        parse({"multi_compile_fwdbase", "multi_compile_domain _ VERTEXLIGHT_ON"}, sink);
    ASSERT_TRUE(kw.has_value());
    EXPECT_FALSE(sink.hasErrors());
    PassKeywords alone = parseOk({"multi_compile_fwdbase"});
    ASSERT_EQ(kw->sets.size(), alone.sets.size());
    for (const KeywordSetDecl& set : kw->sets) {
        if (std::find(set.keywords.begin(), set.keywords.end(), "VERTEXLIGHT_ON") !=
            set.keywords.end()) {
            EXPECT_TRUE(hasStage(set.stages, Stage::Domain));
            EXPECT_TRUE(hasStage(set.stages, Stage::Vertex));
        }
    }
}

TEST(PragmaParser, ProceduralInstancingAddsAKeywordToTheInstancingSet) {
    PassKeywords kw = parseOk({"multi_compile_instancing", "instancing_options procedural:setup"});
    ASSERT_EQ(kw.sets.size(), 1u);
    EXPECT_EQ(kw.sets[0].keywords, (Keywords{"", "INSTANCING_ON", "PROCEDURAL_INSTANCING_ON"}));
    EXPECT_EQ(parseOk({"multi_compile_instancing"}).sets[0].keywords.size(), 2u);
}

TEST(PragmaParser, ReportsEveryErrorOfTheBlock) {
    DiagnosticList sink;
    EXPECT_FALSE(parse({"multi_compile _ A A", "multi_compile_nope _ B", "multi_compile 1X"}, sink));
    EXPECT_EQ(sink.errorCount(), 3u);
}

TEST(PragmaParser, UnknownColumnStaysUnknown) {
    DiagnosticList sink;
    std::vector<PragmaLine> lines = {{"multi_compile A A", SourceLocation{3, 4, 0}}};
    EXPECT_FALSE(parsePragmas(lines, sink));
    ASSERT_EQ(sink.errorCount(), 1u);
    EXPECT_EQ(sink.diagnostics()[0].location, (SourceLocation{3, 4, 0}));
}

}  // namespace
}  // namespace varc::variants
