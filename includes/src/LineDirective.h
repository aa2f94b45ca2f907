// SPDX-License-Identifier: Apache-2.0
// The one place that decides how `#line` directives are written into expanded source.
#pragma once

#include <cstdint>
#include <string>

#include "varc/core/SourceLocation.h"

namespace varc::includes {

// Appends `#line <line> <file>\n` to |out|, meaning "the line after this directive is line
// |line| of source string |file|" (C preprocessor semantics, integer source-string form, so
// glslang's "ERROR: 3:12:" names FileId 3, line 12). Worked example: splicing b.h (FileId 1)
// at line 4 of a.shader (FileId 0, block starting at line 1) gives
//     #line 1 0      <- a.shader line 1 follows
//     ...lines 1-3 of a.shader...
//     #line 1 1      <- b.h line 1 follows (the #include line itself is gone)
//     ...all of b.h...
//     #line 5 0      <- back in a.shader after its line 4
// Every directive varc writes goes through here, so changing the convention (for example to
// the number of the directive's own line) is a one-function change.
void writeLineDirective(std::string& out, uint32_t line, FileId file);

}  // namespace varc::includes
