// SPDX-License-Identifier: Apache-2.0
// UserDefines: the predefined macros take the replacement a program text gives them itself.
#include <gtest/gtest.h>

#include "varc/driver/UserDefines.h"

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace varc::driver {
namespace {

using Macros = std::vector<PredefinedMacro>;

// Definitions of (name, value), in order.
Macros defines(std::initializer_list<std::pair<const char*, const char*>> pairs) {
    Macros macros;
    for (const auto& [name, value] : pairs) {
        macros.push_back({PredefinedMacro::Kind::Define, name, value});
    }
    return macros;
}

const Macros kPreamble =
    defines({{"SHADER_API_VULKAN", "1"}, {"UNITY_PASS_FORWARDBASE", "1"}, {"POINT", "1"}});
const std::string kPreambleText =
    "#define SHADER_API_VULKAN 1\n#define UNITY_PASS_FORWARDBASE 1\n#define POINT 1\n";

// The preamble text |user| makes of |macros|.
std::string adopted(const UserDefines& user, Macros macros) {
    user.adopt(macros);
    return writePreamble(macros);
}

TEST(UserDefines, APassMacroTheTextDefinesTakesTheTextsReplacement) {
    UserDefines user("float4 x;\n#define UNITY_PASS_FORWARDBASE\n#include \"UnityCG.cginc\"\n");
    EXPECT_EQ(adopted(user, kPreamble),
              "#define SHADER_API_VULKAN 1\n#define UNITY_PASS_FORWARDBASE \n#define POINT 1\n");
}

TEST(UserDefines, SpacingCommentsAndCarriageReturnsAreNotPartOfTheReplacement) {
    UserDefines user("  #  define UNITY_PASS_FORWARDBASE   1   // why not\r\n");
    EXPECT_EQ(adopted(user, defines({{"UNITY_PASS_FORWARDBASE", "1"}})),
              "#define UNITY_PASS_FORWARDBASE 1\n");
}

TEST(UserDefines, TheFirstDefinitionWins) {
    UserDefines user(
        "#define UNITY_PASS_FORWARDBASE\n#undef UNITY_PASS_FORWARDBASE\n"
        "#define UNITY_PASS_FORWARDBASE 1\n");
    EXPECT_EQ(adopted(user, defines({{"UNITY_PASS_FORWARDBASE", "1"}})),
              "#define UNITY_PASS_FORWARDBASE \n");
}

// A text's fallback for a predefined macro (`#ifndef SHADER_TARGET` / `#define SHADER_TARGET 25`)
// must not replace the value the driver sets, nor may anything but a pass macro.
TEST(UserDefines, OnlyPassMacrosSayingDefinedAreAdopted) {
    UserDefines user(
        "#ifndef SHADER_TARGET\n#define SHADER_TARGET 25\n#endif\n#define POINT\n"
        "#define UNITY_PASS_SHADOWCASTER 2\n");
    EXPECT_TRUE(user.empty());
    EXPECT_EQ(adopted(user, defines({{"SHADER_TARGET", "45"}, {"POINT", "1"}})),
              "#define SHADER_TARGET 45\n#define POINT 1\n");
}

TEST(UserDefines, FunctionLikeAndContinuedMacrosAndOtherLinesAreLeftAlone) {
    UserDefines user(
        "#define UNITY_PASS_META(x) x\n#define UNITY_PASS_DEFERRED \\\n 1\n"
        "#ifdef UNITY_PASS_FORWARDADD\n");
    EXPECT_TRUE(user.empty());
    EXPECT_EQ(adopted(user, kPreamble), kPreambleText);
}

TEST(UserDefines, NamesThatOnlyStartLikeAPreambleMacroDoNotMatch) {
    UserDefines user("#define UNITY_PASS_FORWARDBASES\n#defined UNITY_PASS_FORWARDBASE\n");
    EXPECT_EQ(adopted(user, kPreamble), kPreambleText);
}

}  // namespace
}  // namespace varc::driver
