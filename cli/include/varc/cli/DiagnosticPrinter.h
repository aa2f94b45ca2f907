// SPDX-License-Identifier: Apache-2.0
// Prints diagnostics clang style: `path:line:col: error: message`, the source line, notes.
#pragma once

#include <iosfwd>
#include <vector>

#include "varc/core/Diagnostic.h"
#include "varc/includes/SourceMap.h"

namespace varc::cli {

// Prints |diagnostics| to |err| in order, then "N errors generated." when there were errors.
// Example:
//   shaders/a.shader:12:21: error: unknown shortcut 'multi_compile_fwdad'; did you mean ...?
//       #pragma multi_compile_fwdad
//               ^
//   shaders/a.shader:5:3: note: while loading pass 0 of shader "A"
void printDiagnostics(const std::vector<Diagnostic>& diagnostics,
                      const includes::SourceMap& sourceMap, std::ostream& err);

}  // namespace varc::cli
