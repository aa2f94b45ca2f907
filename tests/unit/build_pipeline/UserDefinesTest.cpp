// SPDX-License-Identifier: Apache-2.0
// UserDefines: the predefined macros take the replacement a program text gives them itself.
#include "varc/build/UserDefines.h"

#include <gtest/gtest.h>

namespace varc::compiler {
namespace {

constexpr const char* kPreamble =
    "#define SHADER_API_VULKAN 1\n#define UNITY_PASS_FORWARDBASE 1\n#define POINT 1\n";

TEST(UserDefines, APassMacroTheTextDefinesTakesTheTextsReplacement) {
    UserDefines defines("float4 x;\n#define UNITY_PASS_FORWARDBASE\n#include \"UnityCG.cginc\"\n");
    EXPECT_EQ(defines.adopt(kPreamble),
              "#define SHADER_API_VULKAN 1\n#define UNITY_PASS_FORWARDBASE \n#define POINT 1\n");
}

TEST(UserDefines, SpacingCommentsAndCarriageReturnsAreNotPartOfTheReplacement) {
    UserDefines defines("  #  define POINT   2   // why not\r\n");
    EXPECT_EQ(defines.adopt("#define POINT 1\n"), "#define POINT 2\n");
}

TEST(UserDefines, TheFirstDefinitionWins) {
    UserDefines defines("#define POINT 2\n#undef POINT\n#define POINT 3\n");
    EXPECT_EQ(defines.adopt("#define POINT 1\n"), "#define POINT 2\n");
}

TEST(UserDefines, FunctionLikeAndContinuedMacrosAndOtherLinesAreLeftAlone) {
    UserDefines defines("#define POINT(x) x\n#define SPOT 1 \\\n + 2\n#ifdef POINT\n");
    EXPECT_TRUE(defines.empty());
    EXPECT_EQ(defines.adopt(kPreamble), kPreamble);
}

TEST(UserDefines, NamesThatOnlyStartLikeAPreambleMacroDoNotMatch) {
    UserDefines defines("#define POINTS 4\n#defined POINT 5\n");
    EXPECT_EQ(defines.adopt(kPreamble), kPreamble);
}

}  // namespace
}  // namespace varc::compiler
