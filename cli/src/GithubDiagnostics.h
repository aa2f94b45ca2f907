// SPDX-License-Identifier: Apache-2.0
// Prints diagnostics as GitHub Actions workflow commands (`::error file=F,line=L,col=C::MSG`).
#pragma once

#include <iosfwd>
#include <vector>

#include "varc/core/Diagnostic.h"
#include "varc/includes/SourceMap.h"

namespace varc::cli {

// One line per diagnostic: `::error`, `::warning` or `::notice` with file (relative to the
// current folder), line and col when known, the message and then each note on its own line
// ("path:line:col: note: ..."). Escaped as GitHub documents: `%`, CR, LF in the message; also
// `:` and `,` in the properties. Example:
//   ::error file=shaders/a.shader,line=12,col=21::unknown shortcut 'x'%0Ashaders/a.shader:5:3: ...
void printGithubDiagnostics(const std::vector<Diagnostic>& diagnostics,
                            const includes::SourceMap& sourceMap, std::ostream& err);

}  // namespace varc::cli
