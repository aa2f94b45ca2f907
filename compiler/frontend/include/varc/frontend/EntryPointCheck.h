// SPDX-License-Identifier: Apache-2.0
// Checks on an HLSL entry point's signature that glslang does not survive.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace varc::frontend {

// Where an entry-point parameter without a name sits, in |preprocessed|'s own coordinates and
// in the original file's (through the text's `#line <line> <fileId>` directives).
struct UnnamedParameter {
    size_t index = 0;  // 1-based position in the parameter list
    std::string text;  // the parameter as written, e.g. "float"
    size_t file = 0;   // the FileId of the last #line before it (0 without one)
    size_t line = 0;   // 1-based line there
};

// glslang's HLSL front end dereferences a null pointer when an entry point has a parameter with
// a type but no name (KhronosGroup/glslang#4389: `float4 vert(float4 : POSITION)`), which would
// end the whole build. This finds such a parameter in the definition of |entry| in the
// preprocessed HLSL |preprocessed| so the driver can report it instead. Modifiers (in, out,
// inout, uniform, const, triangle, point, line, ...), template arguments and array sizes are
// not names; `(void)` and `()` have no parameters. nullopt when every parameter is named or no
// definition of |entry| is found (glslang then reports what is wrong).
// Example: "float4 vert(float4 : POSITION) : SV_POSITION { ... }", "vert" -> {1, "float4 "...}.
std::optional<UnnamedParameter> findUnnamedEntryParameter(std::string_view preprocessed,
                                                          std::string_view entry);

}  // namespace varc::frontend
