// SPDX-License-Identifier: Apache-2.0
// KeywordProjection with an entry point: lookups made only in the bodies of functions the entry
// point cannot reach, or in groups defining only macros nothing kept uses, are left out, and only
// there; whatever could change the text around them (a #define, unbalanced braces, a macro-made
// name, token pasting, a second definition) keeps them.
#include <gtest/gtest.h>

#include "ProjectionKeywords.h"
#include "varc/driver/KeywordProjection.h"

namespace varc::driver {
namespace {

using testing::keyOf;
using testing::kKeywords;
using testing::namesOf;

// The projection of the variant with every keyword on, with |entry| (or without: "").
std::string projectAll(std::string_view text, std::string entry = "frag") {
    KeywordProjection projection(
        std::make_shared<const ProjectionText>(text, kKeywords, variants::VariantKey{}), "",
        std::move(entry));
    std::optional<variants::VariantKey> observed = projection.observedOf(keyOf("ABCD"));
    return observed ? namesOf(*observed) : "?";
}

// A helper the entry calls tests A; a function nobody calls tests B.
constexpr std::string_view kTwoFunctions = R"(
float helper(float x) {
#ifdef A
    return x * 2;
#else
    return x;
#endif
}
float unused(float x) {
#ifdef B
    return x * 3;
#endif
    return x;
}
float4 frag() : SV_Target { return helper(1); }
)";

std::string withFrag(std::string_view before, std::string_view fragBody = "return helper(1);") {
    std::string text(kTwoFunctions);
    text.replace(
        text.find("float4 frag()"), std::string::npos,
        std::string(before) + "\nfloat4 frag() : SV_Target { " + std::string(fragBody) + " }\n");
    return text;
}

TEST(ReachableProjection, LookupsInAFunctionTheEntryCannotReachAreLeftOut) {
    EXPECT_EQ(projectAll(kTwoFunctions), "A");
    EXPECT_EQ(projectAll(kTwoFunctions, ""), "AB");  // without an entry point: every lookup
    // From another entry point the helper is the unreachable one.
    std::string text(kTwoFunctions);
    text += "float4 frag2() : SV_Target { return unused(1); }\n";
    EXPECT_EQ(projectAll(text, "frag2"), "B");
}

TEST(ReachableProjection, CallsThroughOtherFunctionsAndMacrosReach) {
    EXPECT_EQ(projectAll(withFrag("float relay() { return unused(2); }", "return relay();")), "B");
    EXPECT_EQ(projectAll(withFrag("#define CALL_IT unused(2)", "return CALL_IT;")), "B");
    // A global initializer and a string attribute name what they use.
    EXPECT_EQ(projectAll(withFrag("static float g = unused(3);")), "AB");
    EXPECT_EQ(projectAll(withFrag("[patchconstantfunc(\"unused\")]")), "AB");
    // A prototype counts as a use: it is not worth telling apart.
    EXPECT_EQ(projectAll(withFrag("float unused(float x);")), "AB");
}

TEST(ReachableProjection, TokenPastingReachesEveryFunctionItCouldName) {
    // (The helper is not called here: A is never looked up, B is.)
    EXPECT_EQ(projectAll(withFrag("#define CALL(n) un##n(1)", "return CALL(used);")), "B");
    EXPECT_EQ(projectAll(withFrag("#define CALL(n) n##ed(1)", "return CALL(unus);")), "B");
    // Two parameters pasted: any name may come out, nothing is left out.
    EXPECT_EQ(projectAll(withFrag("#define CAT(a, b) a##b", "return CAT(un, used)(1);")), "AB");
    // A pasting macro nothing reached does not matter.
    EXPECT_EQ(projectAll(withFrag("#define CAT(a, b) a##b")), "A");
}

TEST(ReachableProjection, GroupsThatCouldChangeTheTextAroundTheBodyStillCount) {
    auto unusedBody = [](std::string_view group) {
        std::string text(kTwoFunctions);
        const std::string from = "#ifdef B\n    return x * 3;\n#endif\n";
        text.replace(text.find(from), from.size(), std::string(group));
        return text;
    };
    EXPECT_EQ(projectAll(unusedBody("#ifdef B\n#define SCALE 3\n    x *= SCALE;\n#endif\n")), "AB");
    EXPECT_EQ(projectAll(unusedBody("#ifdef B\n    return x; } float more(float x) {\n#endif\n")),
              "AB");
    EXPECT_EQ(projectAll(unusedBody("#ifdef B\n    if (x > 0) { x = 1; }\n#endif\n")), "A");
    // A nested clean group inside a group holding a #define: only the outer lookup counts.
    EXPECT_EQ(projectAll(unusedBody("#ifdef B\n#define S 1\n#ifdef C\nx = 2;\n#endif\n#endif\n")),
              "AB");
    // Text naming a keyword, a run of lines wholly inside the unreachable body: left out; a
    // run that goes on past the body's end still counts (runs are the unit of a lookup).
    EXPECT_EQ(projectAll(unusedBody("#ifdef C\n#endif\n    x += D;\n#ifdef C\n#endif\n")), "A");
    EXPECT_EQ(projectAll(unusedBody("    x += D;\n")), "AD");
}

TEST(ReachableProjection, DefinitionGroupsCountOnlyWhenWhatKeptCodeUsesTheirMacros) {
    const std::string tint = "#ifdef C\n#define TINT 2\n#endif\n";
    EXPECT_EQ(projectAll(withFrag(tint)), "A");
    EXPECT_EQ(projectAll(withFrag(tint, "return helper(TINT);")), "AC");
    // Through a chain of macros, and through a group of a used macro testing another.
    const std::string chain =
        "#ifdef C\n#define TINT_ON\n#endif\n#ifdef TINT_ON\n"
        "#define TINT 2\n#else\n#define TINT 1\n#endif\n"
        "#define COLOR (TINT * 0.5)\n";
    EXPECT_EQ(projectAll(withFrag(chain)), "A");
    EXPECT_EQ(projectAll(withFrag(chain, "return helper(COLOR);")), "AC");
    // Used only in a body nothing reaches, or only in a group of unused macros: left out.
    std::string deadUse = withFrag(chain);
    deadUse.replace(deadUse.find("return x;\n}"), 9, "return COLOR;");
    EXPECT_EQ(projectAll(deadUse), "A");
    // Defined again outside the group, or by a second group: a variant's choice there could
    // make the other a redefinition (a diagnostic), so the lookup counts.
    EXPECT_EQ(projectAll(withFrag(tint + "#define TINT 3\n")), "AC");
    EXPECT_EQ(projectAll(withFrag(tint + "#ifdef D\n#define TINT 3\n#endif\n")), "ACD");
    // An include spliced twice behind its guard: the second copy is never entered.
    const std::string guarded = "#ifndef GUARD\n#define GUARD\n" + tint + "float4 _X;\n#endif\n";
    EXPECT_EQ(projectAll(withFrag(guarded + guarded)), "A");
    // A group holding anything but definitions counts as before.
    EXPECT_EQ(projectAll(withFrag("#ifdef C\n#define TINT 2\nfloat4 _Tint;\n#endif\n")), "AC");
    // Token pasting that could form the macro's name.
    EXPECT_EQ(projectAll(withFrag(tint + "#define GET(n) TI##n", "return helper(GET(NT));")), "AC");
}

TEST(ReachableProjection, AFunctionWhoseNameAMacroMakesCountsAsReached) {
    std::string text(kTwoFunctions);
    text.replace(text.find("float unused(float x)"), 21,
                 "#define NAME unused\nfloat NAME(float x)");
    EXPECT_EQ(projectAll(text), "AB");
}

TEST(ReachableProjection, MacrosThatOpenAndCloseBlocksAreFollowed) {
    // A buffer a macro opens and another closes: the function after it is at top level again.
    EXPECT_EQ(projectAll("#define BUFFER_START(n) cbuffer n {\n#define BUFFER_END };\n"
                         "BUFFER_START(Props) float4 _Color; BUFFER_END\n" +
                         std::string(kTwoFunctions)),
              "A");
    // Had the tracker not seen the `{`, the helper would look nested and its lookups count;
    // had it not seen the `}`, everything after would be in the buffer.
    EXPECT_EQ(projectAll("#define BUFFER_START(n) cbuffer n {\n"
                         "BUFFER_START(Props) float4 _Color; }\n" +
                         std::string(kTwoFunctions)),
              "A");
}

TEST(ReachableProjection, MacrosExpandingToTooManyBracesLeaveNothingOut) {
    // O24 expands to 2^24 braces: followed in full it would hang the walk.
    std::string text = "#define O0 {\n";
    for (int i = 1; i <= 24; ++i)
        text += "#define O" + std::to_string(i) + " O" + std::to_string(i - 1) + " O" +
                std::to_string(i - 1) + "\n";
    text += "#if 0\nO24\n#endif\n";  // defined, never expanded: harmless
    EXPECT_EQ(projectAll(text + std::string(kTwoFunctions)), "A");
    text += "O24\n";
    EXPECT_EQ(projectAll(text + std::string(kTwoFunctions)), "AB");
}

TEST(ReachableProjection, VariantsAgreeingOnTheReachableLookupsShareAWalk) {
    KeywordProjection projection(
        std::make_shared<const ProjectionText>(kTwoFunctions, kKeywords, variants::VariantKey{}),
        "", "frag");
    for (std::string_view names : {"", "A", "B", "AB", "ABC", "BCD"})
        projection.observedOf(keyOf(names));
    EXPECT_EQ(projection.projections(), 2u);
    EXPECT_EQ(projection.walks(), 2u);
    projection.keepUnreachableLookups();  // the tree starts again, every lookup counts
    EXPECT_EQ(namesOf(*projection.observedOf(keyOf("AB"))), "AB");
    EXPECT_FALSE(projection.leavesOutUnreachable());
}

}  // namespace
}  // namespace varc::driver
