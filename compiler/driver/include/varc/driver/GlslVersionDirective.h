// SPDX-License-Identifier: Apache-2.0
// A GLSLPROGRAM's `#version` directive, put where glslang needs it and mapped to a version Vulkan
// SPIR-V accepts.
#pragma once

#include <string>
#include <string_view>

namespace varc::driver {

// |text| (an expanded GLSL program: varc's `#line` markers, then the user's lines) with its first
// `#version` directive moved to the very first line, because glslang accepts nothing before it
// (Unity's users write comments above it, and varc's markers always precede it). The directive's
// own line is left empty, so every line after it keeps its number (the line added above shifts
// only what precedes varc's first `#line` marker). Applying it twice gives the same
// text as once (the compile step applies it again to the preprocessed, pruned program, where
// glslang's output and varc's markers can precede the directive). Versions Vulkan SPIR-V does not
// take are mapped: `#version 100` (GLSL ES 1.0, as written for Unity's GLES path) is dropped,
// so the program compiles as legacy GLSL with varc's mapping of the old built-ins (see
// GlslLegacyPreamble.h); `#version 300 es` becomes `#version 310 es`, the first ES version
// glslang compiles to SPIR-V, a superset of 3.00. Text without `#version` is returned unchanged.
// Example: "#line 1 2\n// note\n#version 330\nvoid main(){}" ->
//          "#version 330\n#line 1 2\n// note\n\nvoid main(){}".
std::string hoistGlslVersion(std::string_view text);

}  // namespace varc::driver
