// SPDX-License-Identifier: Apache-2.0
// Reads `#pragma surface FUNC MODEL [options]` out of a SubShader's program block.
#pragma once

#include <optional>
#include <string_view>

#include "varc/core/Diagnostic.h"
#include "varc/shaderlab/ShaderAst.h"

namespace varc::shaderlab {

// The location of the `#` of the first `#pragma surface` line in |block|, if it has one.
std::optional<SourceLocation> findSurfacePragma(const ProgramBlock& block);

// Parses the words after `surface` on the pragma line. |text| is the rest of the line after
// the word `surface` (a `//` comment is ignored) and |at| the location of text[0]. Fills
// |out|'s function, lighting model and options. Reports "FUNC and MODEL missing", unknown
// options and options missing their value at the word, and returns false after an error.
// Example: " surf Lambert vertex:vert alphatest:_Cutoff" -> function "surf", model "Lambert",
// vertexFunction "vert", alphaTestProperty "_Cutoff".
bool parseSurfaceOptions(std::string_view text, SourceLocation at, SurfaceProgram& out,
                         DiagnosticSink& sink);

// Builds the SurfaceProgram of |block| whose `#pragma surface` is at |pragma|: the pragma's
// words parsed with parseSurfaceOptions. Returns nullopt after reporting an error.
std::optional<SurfaceProgram> parseSurfaceProgram(const ProgramBlock& block,
                                                  SourceLocation pragma, DiagnosticSink& sink);

}  // namespace varc::shaderlab
