// SPDX-License-Identifier: Apache-2.0
// KeywordProjection: a keyword is kept only where the preprocessor looks it up in the variant's
// branches; indirect tests, nesting, #elif, #undef and conditionally included text stay exact.
#include <gtest/gtest.h>

#include "ProjectionKeywords.h"
#include "varc/driver/KeywordProjection.h"

namespace varc::driver {
namespace {

using testing::keyOf;
using testing::kKeywords;
using testing::namesOf;

struct Projector {
    explicit Projector(std::string_view text, std::string_view base = "",
                       variants::VariantKey formable = {})
        : projection(std::make_shared<const ProjectionText>(text, kKeywords, formable), base) {}

    // The projection of the variant with keywords |names| ("AC": A and C on), or "?" when the
    // analysis gives up.
    std::string operator()(std::string_view names) {
        std::optional<variants::VariantKey> observed = projection.observedOf(keyOf(names));
        return observed ? namesOf(*observed) : "?";
    }

    KeywordProjection projection;
};

TEST(KeywordProjection, NestedConditionsOnlyLookUpInTakenBranches) {
    Projector project("#ifdef A\n#ifdef B\nfloat b;\n#endif\n#endif\n#if 0\nC D\n#endif\n");
    EXPECT_EQ(project("ABCD"), "AB");
    EXPECT_EQ(project("BCD"), "");  // A is off: B is never asked about
    EXPECT_EQ(project("ACD"), "A");
    EXPECT_EQ(project("B"), "");
    EXPECT_EQ(project.projection.projections(), 3u);  // {}, {A}, {A B} (B off or on)
    EXPECT_EQ(project.projection.walks(), 3u);        // the fourth variant reused a walk
}

TEST(KeywordProjection, TheDecisionTreeWalksOncePerDistinctProjection) {
    Projector project("#ifdef A\nfloat a;\n#endif\nfloat c = C;\n// B D\n");
    for (std::string_view names : {"", "A", "B", "AB", "C", "AC", "BC", "ABC", "D", "ABCD"})
        project(names);
    EXPECT_EQ(project("ABCD"), "AC");
    EXPECT_EQ(project.projection.projections(), 4u);
    EXPECT_EQ(project.projection.walks(), 4u);
}

TEST(KeywordProjection, AMacroThatTestsAKeywordIndirectlyLooksItUp) {
    Projector project("#define HAS_B B\n#define ON_C defined(C)\n#if HAS_B || ON_C\nx\n#endif\n");
    EXPECT_EQ(project("BD"), "B");
    EXPECT_EQ(project("CD"), "C");
    EXPECT_EQ(project("AD"), "");
    Projector functionLike("#define ENABLED(x) (x + 0)\n#if ENABLED(B)\ny\n#endif\n");
    EXPECT_EQ(functionLike("AB"), "B");
}

TEST(KeywordProjection, TextLinesLookUpKeywordsThroughMacroBodies) {
    Projector project("#define USE_C C\n#define USE USE_C\nfloat x = USE;\nfloat y = D;\n");
    EXPECT_EQ(project("ACD"), "CD");
    EXPECT_EQ(project("AB"), "");
}

TEST(KeywordProjection, ElifIsOnlyEvaluatedWhenTheBranchesBeforeItFailed) {
    Projector project("#if defined(A)\nx\n#elif defined(B)\ny\n#elif C\nz\n#else\nD\n#endif\n");
    EXPECT_EQ(project("ABCD"), "A");
    EXPECT_EQ(project("BCD"), "B");
    EXPECT_EQ(project("CD"), "C");
    EXPECT_EQ(project("D"), "D");  // the #else branch names D
}

TEST(KeywordProjection, UndefIsALookUpAndHidesTheKeywordFromLaterTests) {
    Projector project("#ifdef A\n#undef B\n#endif\n#ifdef B\nfloat c = C;\n#endif\n");
    EXPECT_EQ(project("ABC"), "AB");  // B undefined by the text: C's line is skipped
    EXPECT_EQ(project("BC"), "BC");
    EXPECT_EQ(project("C"), "");
}

TEST(KeywordProjection, ConditionallyIncludedTextCountsOnlyWhenItsBranchIsTaken) {
    // An include spliced by the front end under a condition, with its #line mapping.
    Projector project(
        "#ifdef A\n#line 1 \"Lighting.cginc\"\n#ifdef B\nfloat b;\n#endif\nfloat c = C;\n"
        "#line 4 \"main.shader\"\n#endif\n");
    EXPECT_EQ(project("BC"), "");
    EXPECT_EQ(project("ABC"), "ABC");
    EXPECT_EQ(project("AC"), "AC");
}

TEST(KeywordProjection, ThePreambleDecidesBranchesAndCommentsHideDirectives) {
    Projector project(
        "#if SHADER_TARGET >= 30\n#ifdef A\nx\n#endif\n#else\n#ifdef B\ny\n#endif\n#endif\n"
        "// #ifdef C\n/* #ifdef D */\n",
        "#define SHADER_TARGET 35\n");
    EXPECT_EQ(project("ABCD"), "A");
    EXPECT_EQ(project("BCD"), "");
}

TEST(KeywordProjection, KeywordsTokenPastingCanFormAreAlwaysObserved) {
    variants::VariantKey formable;
    formable.set(3);  // D
    Projector project("#ifdef A\nx\n#endif\n", "", formable);
    EXPECT_EQ(project("ABD"), "AD");
    EXPECT_EQ(project("BD"), "D");
}

TEST(KeywordProjection, GivesUpOnWhatItDoesNotModel) {
    EXPECT_EQ(Projector("#ifdef GL_ES\nx\n#endif\n#ifdef A\n#endif\n")("A"), "?");
    EXPECT_EQ(Projector("#ifdef A\nx\n")("A"), "?");  // no #endif
    EXPECT_EQ(Projector("#if 1.5 > A\n#endif\n")("A"), "?");
    EXPECT_EQ(Projector("#define P(x) x##1\n#if P(A)\n#endif\n")("A"), "?");
    // A branch not taken may hold anything: it is not evaluated.
    EXPECT_EQ(Projector("#if 0\n#if 1.5\n#endif\n#endif\n#ifdef A\n#endif\n")("A"), "A");
}

}  // namespace
}  // namespace varc::driver
