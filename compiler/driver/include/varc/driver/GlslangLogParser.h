// SPDX-License-Identifier: Apache-2.0
// Turns glslang's info log into Diagnostics located in the original files.
#pragma once

#include <string_view>
#include <vector>

#include "varc/core/Diagnostic.h"
#include "varc/includes/SourceMap.h"

namespace varc::driver {

// The one place glslang's log format is understood. Log lines look like
//   ERROR: 3:16: 'undefinedThing' : unknown variable
//   WARNING: 0:4: 'x' : ...
//   ERROR: 2 compilation errors.  No code generated.
// where "3" is the source-string number, which varc's `#line <line> <fileId>` directives make
// equal to a SourceMap FileId. Each ERROR/WARNING line becomes one Diagnostic at
// (fileId, line, column), the column recovered by finding the quoted token on the original
// line ('undefinedThing' -> its first whole-word occurrence), 0 when not found. Summary lines
// ("N compilation errors", "HLSL parsing failed") are dropped; unrecognised non-empty lines
// become errors without a location; exact duplicates are dropped.
// Example: "ERROR: 3:16: 'foo' : undeclared identifier" -> {Error, {3, 16, 9}, "undeclared
// identifier 'foo'"} when line 16 of file 3 is "float4 x=foo;".
std::vector<Diagnostic> parseGlslangLog(std::string_view log, const includes::SourceMap& sourceMap);

}  // namespace varc::driver
