// SPDX-License-Identifier: Apache-2.0
// Maps legacy GLSL built-ins (gl_Vertex, gl_ModelViewProjectionMatrix, gl_FragColor, ...) onto
// declarations that Vulkan SPIR-V accepts.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "varc/core/Stage.h"

namespace varc::driver {

// The GLSL version assumed for GLSLPROGRAM blocks without `#version`: the lowest glslang accepts
// for Vulkan, compiled with its relaxed Vulkan rules (loose uniforms go to one default block).
inline constexpr int kLegacyGlslVersion = 140;

// Declarations plus `#define gl_X varc_X` lines for |stage|, for the
// legacy built-ins that |source| mentions (so unused ones add no inputs or uniforms). Names
// starting with `gl_` cannot be declared, but they can be #defined, which is what makes this
// work. Also maps `varying` to `out` (vertex) or `in` (fragment). The runtime fills the
// `varc_*` uniforms by name (docs/SHADER_ABI.md).
// Example, vertex stage, source using gl_Vertex:
//   in vec4 varc_Vertex;
//   #define gl_Vertex varc_Vertex
//   #define varying out
std::string legacyGlslPreamble(std::string_view source, Stage stage);

// varc's `#line N F` directives mean "the next line is N" (C and HLSL). GLSL before 3.30 (and
// ES before 3.00) reads `#line N` as numbering the directive's own line N instead (glslang's
// lineDirectiveShouldSetNextLine), so for those versions each directive is rewritten to
// `#line N-1 F`. |source| is expanded GLSL; its `#version`, if any, decides (default 140).
// Example: "#line 12 3" -> "#line 11 3" for a source without #version.
std::string toGlslLineConvention(std::string_view source);

}  // namespace varc::driver
