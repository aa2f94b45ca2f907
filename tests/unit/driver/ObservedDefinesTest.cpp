// SPDX-License-Identifier: Apache-2.0
// ObservedNames / dropUnobservedDefines: a define may only be dropped when no expansion of the
// text can name it, token pasting included.
#include <gtest/gtest.h>

#include "varc/driver/ObservedDefines.h"

namespace varc::driver {
namespace {

TEST(ObservedNames, SeesIdentifiersButNotNumbersOrPartsOfNames) {
    ObservedNames names(
        "#if defined(POINT) && SPOT_COOKIE\nfloat x = 1.0f + 0x1F; // DIRECTIONAL\n");
    EXPECT_TRUE(names.mayObserve("POINT"));
    EXPECT_TRUE(names.mayObserve("SPOT_COOKIE"));
    EXPECT_TRUE(names.mayObserve("DIRECTIONAL"));  // in a comment: conservative
    EXPECT_FALSE(names.mayObserve("SPOT"));        // only part of SPOT_COOKIE
    EXPECT_FALSE(names.mayObserve("f"));           // the suffix of 1.0f
    EXPECT_FALSE(names.mayObserve("x1F"));
    EXPECT_FALSE(names.mayObserve("VERTEXLIGHT_ON"));
}

TEST(ObservedNames, PragmaLinesAreNotExpandedSoTheirNamesAreNotObserved) {
    ObservedNames names(
        "#pragma multi_compile _ SHADOWS_SCREEN\n  # pragma target 3.0\n"
        "#pragmatic_thing\nfloat pragma_POINT;\n");
    EXPECT_FALSE(names.mayObserve("SHADOWS_SCREEN"));
    EXPECT_FALSE(names.mayObserve("target"));
    EXPECT_TRUE(names.mayObserve("pragmatic_thing"));  // not a #pragma directive
    EXPECT_TRUE(names.mayObserve("pragma_POINT"));
}

TEST(ObservedNames, PastingWithALiteralEndConstrainsTheFormedName) {
    ObservedNames names(
        "#define COORDS(idx) float4 c : TEXCOORD##idx;\n"
        "#define TRANSFORM_TEX(tex, name) (tex.xy * name##_ST.xy)\n");
    EXPECT_TRUE(names.mayObserve("TEXCOORD7"));  // TEXCOORD ## idx
    EXPECT_TRUE(names.mayObserve("POINT_ST"));   // name ## _ST
    EXPECT_FALSE(names.mayObserve("POINT"));
    EXPECT_FALSE(names.mayObserve("SHADER_STAGE_VERTEX"));
}

TEST(ObservedNames, PastingTwoParametersFormsConcatenationsOfTheTextsTokens) {
    ObservedNames names("#define CAT(a, b) a ## b\n#if CAT(PO, INT)\n#endif\n");
    EXPECT_TRUE(names.mayObserve("POINT"));      // PO ## INT
    EXPECT_TRUE(names.mayObserve("POINTPO"));    // CAT(CAT(PO, INT), PO) through another macro
    EXPECT_TRUE(names.mayObserve("INT2"));       // a number argument: INT ## 2
    EXPECT_FALSE(names.mayObserve("ANYTHING"));  // no split into the text's tokens
    EXPECT_FALSE(names.mayObserve("SHADER_STAGE_VERTEX"));
    // A name a literal-ended chain forms is a piece too: P(OINT) forms POINT_X, then X ## Y.
    ObservedNames mixed("#define P(x) x##_X\n#define CAT(a, b) a##b\nSP\n");
    EXPECT_TRUE(mixed.mayObserve("SPOT_X"));
    EXPECT_TRUE(mixed.mayObserve("SPSPOT_X"));  // SP ## SPOT_X
    EXPECT_FALSE(mixed.mayObserve("SPOT"));
}

TEST(ObservedNames, AChainIsJudgedByItsEnds) {
    ObservedNames names("#define JOIN(a, b) a##_##b\nJOIN(SHADOWS, SCREEN)\n");  // <a>_<b>
    EXPECT_TRUE(names.mayObserve("SHADOWS_SCREEN"));
    EXPECT_FALSE(names.mayObserve("SHADOWS_SOFT"));
    ObservedNames prefixed("#define P(x) UNITY_##x##_ON\n");  // forms UNITY_<x>_ON
    EXPECT_TRUE(prefixed.mayObserve("UNITY_HDR_ON"));
    EXPECT_FALSE(prefixed.mayObserve("VERTEXLIGHT_ON_X"));
}

TEST(ObservedNames, PastesInContinuedDefinesAndObjectMacrosCount) {
    ObservedNames continued("#define DECL(n) \\\n    float n; \\\n    float SPOT##n;\n");
    EXPECT_TRUE(continued.mayObserve("SPOT_COOKIE"));  // SPOT ## n on a continuation line
    ObservedNames object("#define X PO##INT\n");       // both literal: forms exactly POINT
    EXPECT_TRUE(object.mayObserve("POINT"));
}

TEST(DropUnobservedMacros, KeepsObservedDefinitionsAndEveryUndef) {
    ObservedNames names("#ifdef POINT\n#endif\n");
    using Kind = PredefinedMacro::Kind;
    std::vector<PredefinedMacro> macros = {{Kind::Define, "SHADER_STAGE_VERTEX", "1"},
                                           {Kind::Define, "POINT", "1"},
                                           {Kind::Define, "SPOT", "1"},
                                           {Kind::Undef, "GL_core_profile", ""}};
    dropUnobservedMacros(macros, names);
    EXPECT_EQ(writePreamble(macros), "#define POINT 1\n#undef GL_core_profile\n");
}

TEST(DropUnobservedMacros, AFunctionLikeMacroIsObservedByItsName) {
    using Kind = PredefinedMacro::Kind;
    std::vector<PredefinedMacro> macros = {{Kind::Define, "GetRenderTargetSampleCount()", "(1u)"}};
    dropUnobservedMacros(macros, ObservedNames("uint n = GetRenderTargetSampleCount();\n"));
    EXPECT_EQ(macros.size(), 1u);
    dropUnobservedMacros(macros, ObservedNames("float4 x;\n"));
    EXPECT_TRUE(macros.empty());
}

}  // namespace
}  // namespace varc::driver
