// SPDX-License-Identifier: Apache-2.0
// UserDefines: the predefined macros take the replacement a program text gives them itself.
#include <gtest/gtest.h>

#include "varc/driver/UserDefines.h"

namespace varc::driver {
namespace {

constexpr const char* kPreamble =
    "#define SHADER_API_VULKAN 1\n#define UNITY_PASS_FORWARDBASE 1\n#define POINT 1\n";

TEST(UserDefines, APassMacroTheTextDefinesTakesTheTextsReplacement) {
    UserDefines defines("float4 x;\n#define UNITY_PASS_FORWARDBASE\n#include \"UnityCG.cginc\"\n");
    EXPECT_EQ(defines.adopt(kPreamble),
              "#define SHADER_API_VULKAN 1\n#define UNITY_PASS_FORWARDBASE \n#define POINT 1\n");
}

TEST(UserDefines, SpacingCommentsAndCarriageReturnsAreNotPartOfTheReplacement) {
    UserDefines defines("  #  define UNITY_PASS_FORWARDBASE   1   // why not\r\n");
    EXPECT_EQ(defines.adopt("#define UNITY_PASS_FORWARDBASE 1\n"),
              "#define UNITY_PASS_FORWARDBASE 1\n");
}

TEST(UserDefines, TheFirstDefinitionWins) {
    UserDefines defines(
        "#define UNITY_PASS_FORWARDBASE\n#undef UNITY_PASS_FORWARDBASE\n"
        "#define UNITY_PASS_FORWARDBASE 1\n");
    EXPECT_EQ(defines.adopt("#define UNITY_PASS_FORWARDBASE 1\n"),
              "#define UNITY_PASS_FORWARDBASE \n");
}

// A text's fallback for a predefined macro (`#ifndef SHADER_TARGET` / `#define SHADER_TARGET 25`)
// must not replace the value the driver sets, nor may anything but a pass macro.
TEST(UserDefines, OnlyPassMacrosSayingDefinedAreAdopted) {
    UserDefines defines(
        "#ifndef SHADER_TARGET\n#define SHADER_TARGET 25\n#endif\n#define POINT\n"
        "#define UNITY_PASS_SHADOWCASTER 2\n");
    EXPECT_TRUE(defines.empty());
    EXPECT_EQ(defines.adopt("#define SHADER_TARGET 45\n#define POINT 1\n"),
              "#define SHADER_TARGET 45\n#define POINT 1\n");
}

TEST(UserDefines, FunctionLikeAndContinuedMacrosAndOtherLinesAreLeftAlone) {
    UserDefines defines(
        "#define UNITY_PASS_META(x) x\n#define UNITY_PASS_DEFERRED \\\n 1\n"
        "#ifdef UNITY_PASS_FORWARDADD\n");
    EXPECT_TRUE(defines.empty());
    EXPECT_EQ(defines.adopt(kPreamble), kPreamble);
}

TEST(UserDefines, NamesThatOnlyStartLikeAPreambleMacroDoNotMatch) {
    UserDefines defines("#define UNITY_PASS_FORWARDBASES\n#defined UNITY_PASS_FORWARDBASE\n");
    EXPECT_EQ(defines.adopt(kPreamble), kPreamble);
}

}  // namespace
}  // namespace varc::driver
