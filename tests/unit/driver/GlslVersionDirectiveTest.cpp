// SPDX-License-Identifier: Apache-2.0
// hoistGlslVersion: a GLSLPROGRAM's #version goes first, lines keep their numbers, ES versions
// map to ones Vulkan SPIR-V accepts.
#include <gtest/gtest.h>

#include "varc/driver/GlslVersionDirective.h"

namespace varc::driver {
namespace {

TEST(GlslVersionDirective, TheDirectiveMovesAboveMarkersAndCommentsAndLeavesItsLineEmpty) {
    EXPECT_EQ(hoistGlslVersion("#line 8 0\n// note\n  #  version 330\nvoid main(){}\n"),
              "#version 330\n#line 8 0\n// note\n\nvoid main(){}\n");
}

TEST(GlslVersionDirective, TextWithoutAVersionIsUnchanged) {
    const char* text = "#line 1 0\n// #version 330 in a comment is not a directive\nvoid main(){}\n";
    EXPECT_EQ(hoistGlslVersion(text), text);
    EXPECT_EQ(hoistGlslVersion("#versions 330\n"), "#versions 330\n");
}

TEST(GlslVersionDirective, GlslEs300BecomesTheFirstEsVersionSpirvTakes) {
    EXPECT_EQ(hoistGlslVersion("#line 1 0\n#version 300 es\r\nx\n"),
              "#version 310 es\n#line 1 0\n\nx\n");
}

// GLSL ES 1.00 (Unity's GLES path) compiles as legacy GLSL: the directive goes.
TEST(GlslVersionDirective, GlslEs100IsDropped) {
    EXPECT_EQ(hoistGlslVersion("#line 1 0\n#version 100\nx\n"), "#line 1 0\n\nx\n");
}

TEST(GlslVersionDirective, ApplyingItTwiceGivesWhatOnceGives) {
    std::string once = hoistGlslVersion("\nin vec4 v;\n#version 300 es\n#line 13 0\nx\n");
    EXPECT_EQ(once, "#version 310 es\n\nin vec4 v;\n\n#line 13 0\nx\n");
    EXPECT_EQ(hoistGlslVersion(once), once);
}

}  // namespace
}  // namespace varc::driver
