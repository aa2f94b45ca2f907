// SPDX-License-Identifier: Apache-2.0
// Prints diagnostics as a SARIF 2.1.0 log (`--diagnostics-format sarif`), for code scanning.
#pragma once

#include <iosfwd>
#include <vector>

#include "varc/cli/DiagnosticOutput.h"

namespace varc::cli {

// One run: tool.driver "varc" with its version and the four rules (DiagnosticRule); one result
// per diagnostic with ruleId, level (error, warning, note), message, the physical location
// (artifactLocation.uri relative to the current folder where possible, region startLine and
// startColumn when known) and the notes as relatedLocations (the include chain, the pass and
// stage, the pragma lines). Pretty-printed JSON, then a newline.
void printSarifDiagnostics(const std::vector<RuledDiagnostic>& diagnostics,
                           const includes::SourceMap& sourceMap, std::ostream& err);

}  // namespace varc::cli
