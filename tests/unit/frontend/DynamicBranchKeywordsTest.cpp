// SPDX-License-Identifier: Apache-2.0
// dynamic_branch keywords: their uniform declarations and the warnings on preprocessor tests.
#include <gtest/gtest.h>

#include "varc/frontend/DynamicBranchKeywords.h"

namespace varc::frontend {
namespace {

using Names = std::vector<std::string>;

variants::KeywordSetDecl dynamicSet(Names keywords, SourceLocation location) {
    variants::KeywordSetDecl set;
    set.kind = variants::DirectiveKind::DynamicBranch;
    set.directive = "dynamic_branch";
    set.keywords = std::move(keywords);
    set.location = location;
    return set;
}

variants::PassKeywords twoDynamicSets() {
    variants::PassKeywords keywords;
    keywords.dynamicBranches.push_back(dynamicSet({"", "RED", "GREEN"}, {2, 7, 1}));
    keywords.dynamicBranches.push_back(dynamicSet({"BLUE", "RED"}, {3, 4, 1}));
    keywords.sets.push_back(dynamicSet({"", "VARIANT"}, {2, 8, 1}));  // not dynamic
    return keywords;
}

// The warnings |text| gets for |names|, each "file:line:column message".
std::vector<Diagnostic> warningsFor(std::string_view text, const Names& names) {
    DiagnosticList sink;
    std::vector<SourceLocation> reported;
    warnPreprocessorTestsOfDynamicBranches(text, names, reported, sink);
    for (const Diagnostic& diagnostic : sink.diagnostics())
        EXPECT_EQ(diagnostic.severity, Severity::Warning);
    return sink.diagnostics();
}

std::vector<SourceLocation> locationsOf(const std::vector<Diagnostic>& diagnostics) {
    std::vector<SourceLocation> locations;
    for (const Diagnostic& diagnostic : diagnostics) locations.push_back(diagnostic.location);
    return locations;
}

TEST(DynamicBranchKeywords, KeywordsComeInDeclarationOrderOnceWithoutTheEmptyEntry) {
    EXPECT_EQ(dynamicBranchKeywords(twoDynamicSets()), (Names{"RED", "GREEN", "BLUE"}));
    EXPECT_TRUE(dynamicBranchKeywords(variants::PassKeywords{}).empty());
}

TEST(DynamicBranchKeywords, HlslDeclaresIntegersAtEachPragmaBeforeTheText) {
    std::string text = "#line 1 2\nfloat4 f() : SV_Target { if (RED) return 1; return 0; }\n";
    EXPECT_EQ(declareDynamicBranchUniforms(text, twoDynamicSets(), shaderlab::ProgramLanguage::Cg),
              "#line 7 2\nint RED; int GREEN;\n#line 4 3\nint BLUE;\n" + text);
    EXPECT_EQ(
        declareDynamicBranchUniforms(text, twoDynamicSets(), shaderlab::ProgramLanguage::Hlsl),
        "#line 7 2\nint RED; int GREEN;\n#line 4 3\nint BLUE;\n" + text);
}

TEST(DynamicBranchKeywords, GlslDeclaresLooseUniforms) {
    std::string text = "#line 1 2\nvoid main() {}\n";
    EXPECT_EQ(
        declareDynamicBranchUniforms(text, twoDynamicSets(), shaderlab::ProgramLanguage::Glsl),
        "#line 7 2\nuniform int RED; uniform int GREEN;\n#line 4 3\nuniform int BLUE;\n" + text);
}

TEST(DynamicBranchKeywords, TextWithoutDynamicKeywordsIsUnchanged) {
    variants::PassKeywords keywords;
    keywords.dynamicBranches.push_back(dynamicSet({""}, {2, 7, 1}));
    std::string text = "#line 1 2\nfloat x;\n";
    EXPECT_EQ(declareDynamicBranchUniforms(text, keywords, shaderlab::ProgramLanguage::Cg), text);
    EXPECT_EQ(declareDynamicBranchUniforms(text, {}, shaderlab::ProgramLanguage::Cg), text);
}

TEST(DynamicBranchKeywords, EveryConditionalFormIsReportedAtTheKeyword) {
    std::string text =
        "#line 10 4\n"
        "#ifdef RED\n"  // 4:10:8
        "#endif\n"
        "#ifndef RED\n"  // 4:12:9
        "#endif\n"
        "#if RED\n"                    // 4:14:5
        "#elif defined(GREEN) || X\n"  // 4:15:15
        "#endif\n"
        "  #  if !defined( RED ) && VARIANT\n"  // 4:17:19
        "#endif\n";
    auto warnings = warningsFor(text, {"RED", "GREEN"});
    EXPECT_EQ(locationsOf(warnings),
              (std::vector<SourceLocation>{
                  {4, 10, 8}, {4, 12, 9}, {4, 14, 5}, {4, 15, 15}, {4, 17, 19}}));
    ASSERT_EQ(warnings.size(), 5u);
    EXPECT_NE(warnings[0].message.find("'#ifdef RED' is always false"), std::string::npos);
    EXPECT_NE(warnings[1].message.find("'#ifndef RED' is always true"), std::string::npos);
    EXPECT_NE(warnings[2].message.find("'#if' reads RED as an undefined macro"), std::string::npos);
    EXPECT_NE(warnings[3].message.find("'#elif' reads GREEN"), std::string::npos);
    EXPECT_NE(warnings[3].message.find("test it with 'if (GREEN)'"), std::string::npos);
    EXPECT_NE(warnings[0].message.find("dynamic_branch keyword"), std::string::npos);
}

TEST(DynamicBranchKeywords, CodeCommentsOtherDirectivesAndLongerNamesAreNotReported) {
    std::string text =
        "#line 1 0\n"
        "if (RED) { x = RED; }\n"
        "#define USE_RED RED\n"
        "#if REDDER || _RED || RED_2\n"
        "#endif\n"
        "// #ifdef RED\n"
        "/* start\n"
        "#ifdef RED\n"
        "end */\n"
        "#if X // RED\n"
        "#endif\n"
        "#if X /* RED */ || Y\n"
        "#endif\n";
    EXPECT_TRUE(warningsFor(text, {"RED"}).empty());
}

TEST(DynamicBranchKeywords, ContinuedConditionsAndLineMappingAreFollowed) {
    std::string text =
        "#line 5 1\n"
        "#if X || \\\n"
        "    defined(RED)\n"  // 1:6:13
        "#endif\n"
        "#line\n"       // malformed: not a mapping, the numbering goes on
        "#ifdef RED\n"  // 1:9:8
        "#line 40 2\n"
        "a /* comment\n"
        "   ends */ b\n"
        "#ifdef RED\n";  // 2:42:8
    EXPECT_EQ(locationsOf(warningsFor(text, {"RED"})),
              (std::vector<SourceLocation>{{1, 6, 13}, {1, 9, 8}, {2, 42, 8}}));
}

TEST(DynamicBranchKeywords, ALocationIsReportedOnce) {
    DiagnosticList sink;
    std::vector<SourceLocation> reported;
    std::string text = "#line 3 1\n#ifdef RED\n#endif\n";
    warnPreprocessorTestsOfDynamicBranches(text, {"RED"}, reported, sink);
    warnPreprocessorTestsOfDynamicBranches(text, {"RED"}, reported, sink);  // another pass
    EXPECT_EQ(sink.diagnostics().size(), 1u);
    EXPECT_TRUE(warningsFor(text, {}).empty());
}

}  // namespace
}  // namespace varc::frontend
