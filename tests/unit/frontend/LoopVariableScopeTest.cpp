// SPDX-License-Identifier: Apache-2.0
// hoistLoopVariables: a `for` header's variable in the enclosing block, as fxc scopes it.
#include <gtest/gtest.h>

#include <algorithm>

#include "varc/frontend/LoopVariableScope.h"

namespace varc::frontend {
namespace {

TEST(LoopVariableScope, ASecondLoopReusesTheFirstLoopsVariable) {
    std::string text =
        "float f() {\n"
        "  float a = 0;\n"
        "  for (int i = -2; i < 0; i += 1) a += i;\n"
        "  for (i = 1; i <= 2; i += 1) a += i;\n"
        "  return a + i;\n}\n";
    EXPECT_EQ(hoistLoopVariables(text, {"i"}),
              "float f() {\n"
              "  float a = 0;\n"
              "  int i; for ( i = -2; i < 0; i += 1) a += i;\n"
              "  for (i = 1; i <= 2; i += 1) a += i;\n"
              "  return a + i;\n}\n");
}

TEST(LoopVariableScope, ARedeclarationInTheSameBlockBecomesAnAssignment) {
    std::string text =
        "void f() { for (uint k = 0; k < 2; k++) {} for (uint k = 5; k < 6; k++) {} "
        "k = 0; }";
    EXPECT_EQ(hoistLoopVariables(text, {"k"}),
              "void f() { uint k; for ( k = 0; k < 2; k++) {} for ( k = 5; k < 6; k++) {} "
              "k = 0; }");
}

TEST(LoopVariableScope, OnlyTheNamesGlslangReportedAreTouched) {
    std::string text = "void f() { for (int i = 0; i < 2; i++) {} for (int j = 0; j < 2; j++) {} }";
    EXPECT_EQ(hoistLoopVariables(text, {}), text);
    EXPECT_EQ(hoistLoopVariables(text, {"j"}),
              "void f() { for (int i = 0; i < 2; i++) {} int j; for ( j = 0; j < 2; j++) {} }");
}

TEST(LoopVariableScope, EachBlockGetsItsOwnDeclaration) {
    std::string text =
        "void f() { { for (int i = 0; i < 1; i++) {} i = 2; } "
        "{ for (int i = 0; i < 1; i++) {} i = 3; } }";
    EXPECT_EQ(hoistLoopVariables(text, {"i"}),
              "void f() { { int i; for ( i = 0; i < 1; i++) {} i = 2; } "
              "{ int i; for ( i = 0; i < 1; i++) {} i = 3; } }");
}

TEST(LoopVariableScope, SeveralDeclaratorsAnotherTypeOrAnOwnDeclarationAreLeftAlone) {
    std::string several = "void f() { for (int i = 0, j = 0; i < 2; i++) {} i = j; }";
    EXPECT_EQ(hoistLoopVariables(several, {"i", "j"}), several);
    std::string declared = "void f() { int i = 4; for (int i = 0; i < 2; i++) {} }";
    EXPECT_EQ(hoistLoopVariables(declared, {"i"}), declared);
    std::string otherType =
        "void f() { for (int i = 0; i < 2; i++) {} for (float i = 0; i < 1; i++) {} }";
    EXPECT_EQ(hoistLoopVariables(otherType, {"i"}),
              "void f() { int i; for ( i = 0; i < 2; i++) {} for (float i = 0; i < 1; i++) {} }");
}

TEST(LoopVariableScope, TheDeclarationGoesBeforeTheLoopsAttributes) {
    std::string text = "void f() { [unroll(4)] [fastopt] for (int i = 0; i < 2; i++) {} i = 1; }";
    EXPECT_EQ(hoistLoopVariables(text, {"i"}),
              "void f() { int i; [unroll(4)] [fastopt] for ( i = 0; i < 2; i++) {} i = 1; }");
}

TEST(LoopVariableScope, LinesAreKept) {
    std::string text = "void f() {\n#line 40 2\n for (int i = 0;\n i < 2; i++) {}\n i = 1; }\n";
    std::string hoisted = hoistLoopVariables(text, {"i"});
    EXPECT_EQ(std::count(hoisted.begin(), hoisted.end(), '\n'),
              std::count(text.begin(), text.end(), '\n'));
    EXPECT_NE(hoisted.find("#line 40 2\n int i; for ( i = 0;"), std::string::npos) << hoisted;
}

}  // namespace
}  // namespace varc::frontend
