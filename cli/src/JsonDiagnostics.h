// SPDX-License-Identifier: Apache-2.0
// Prints diagnostics as one JSON document (`--diagnostics-format json`).
#pragma once

#include <iosfwd>
#include <vector>

#include "varc/cli/DiagnosticOutput.h"

namespace varc::cli {

// {"diagnostics": [{"severity": "error", "rule": "varc.compile", "file": "s/a.shader",
//   "line": 12, "column": 3, "message": "...", "notes": [{"file", "line", "column",
//   "message"}]}], "errors": 1, "warnings": 0}
// file is relative to the current folder where possible, null when unknown; line and column
// are 0 when unknown. One line, then a newline.
void printJsonDiagnostics(const std::vector<RuledDiagnostic>& diagnostics,
                          const includes::SourceMap& sourceMap, std::ostream& err);

}  // namespace varc::cli
