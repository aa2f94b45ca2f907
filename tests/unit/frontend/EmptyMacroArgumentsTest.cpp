// SPDX-License-Identifier: Apache-2.0
// expandEmptyMacroArguments: one-parameter macros called with nothing (or `##`) as argument.
#include <gtest/gtest.h>

#include "varc/frontend/EmptyMacroArguments.h"

namespace varc::frontend {
namespace {

TEST(EmptyMacroArguments, AnEmptyOrPasteOnlyArgumentExpandsTheBodyOnTheCallLine) {
    std::string text =
        "#define DECL(id) \\\n    float _A##id;   \\\n    float _B ## id;\n"
        "DECL()\n#ifdef OLD\n  DECL( ## );\n#endif\nDECL(2)\n";
    EXPECT_EQ(expandEmptyMacroArguments(text),
              "#define DECL(id) \\\n    float _A##id;   \\\n    float _B ## id;\n"
              "     float _A;       float _B;\n#ifdef OLD\n       float _A;       float _B;;\n"
              "#endif\nDECL(2)\n");
}

TEST(EmptyMacroArguments, TheLastDefinitionBeforeTheCallIsUsed) {
    EXPECT_EQ(expandEmptyMacroArguments("#define M(x) one x\nM()\n#undef M\n#define M(x) two\nM()"),
              "#define M(x) one x\n one \n#undef M\n#define M(x) two\n two");
}

TEST(EmptyMacroArguments, OtherPastesStringsAndCallsStayAsWritten) {
    for (std::string text : {"#define M(x) a##b x\nM()\n", "#define M(x) #x\nM()\n",
                             "#define M(x, y) x y\nM(,)\n", "#define M(x) x\nM(1) NM() M\n"}) {
        EXPECT_EQ(expandEmptyMacroArguments(text), text) << text;
    }
}

}  // namespace
}  // namespace varc::frontend
