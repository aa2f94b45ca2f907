// SPDX-License-Identifier: Apache-2.0
// Macro redefinitions: the names glslang reports, and #undef inserted with the mapping kept.
#include <gtest/gtest.h>

#include "varc/frontend/MacroRedefinitions.h"

namespace varc::frontend {
namespace {

TEST(MacroRedefinitions, NamesComeFromGlslangsLogOnceEach) {
    std::string log =
        "ERROR: 9:9: '#define' : Macro redefined; different substitutions: PI\n"
        "ERROR: 3:2: '#define' : Macro redefined; different substitutions: TAU_2\n"
        "ERROR: 9:30: '#define' : Macro redefined; different substitutions: PI\n"
        "ERROR: 1:1: 'x' : undeclared identifier\n";
    EXPECT_EQ(redefinedMacros(log), (std::vector<std::string>{"PI", "TAU_2"}));
    EXPECT_TRUE(redefinedMacros("ERROR: 1:1: 'x' : undeclared identifier\n").empty());
}

TEST(MacroRedefinitions, EveryLaterDefinitionIsPrecededByAnUndefAndItsOwnLine) {
    std::string text =
        "#line 1 0\n#define PI 3.14\nfloat a;\n#line 9 2\n  #  define PI 3.1416\n"
        "#define E 2.7\n#define PI 3\nx\n";
    EXPECT_EQ(undefineBeforeRedefinitions(text, {"PI"}),
              "#line 1 0\n#define PI 3.14\nfloat a;\n#line 9 2\n#undef PI\n#line 9 2\n"
              "  #  define PI 3.1416\n#define E 2.7\n#undef PI\n#line 11 2\n#define PI 3\nx\n");
}

TEST(MacroRedefinitions, OtherNamesAndNamesThatOnlyStartAlikeAreLeftAlone) {
    std::string text = "#line 1 0\n#define PI 1\n#define PIE 2\n#define PIE 3\n#undef PI\n";
    EXPECT_EQ(undefineBeforeRedefinitions(text, {"PI"}), text);
}

}  // namespace
}  // namespace varc::frontend
