// SPDX-License-Identifier: Apache-2.0
// Reads `#pragma` lines into PassKeywords, expanding Unity's multi_compile_* shortcuts.
#include "varc/variants/PragmaParser.h"

#include "pragma/PragmaReader.h"

namespace varc::variants {

std::optional<PassKeywords> parsePragmas(const std::vector<PragmaLine>& pragmas,
                                         DiagnosticSink& sink) {
    PragmaReader reader(sink);
    for (const PragmaLine& line : pragmas) reader.read(line);
    return reader.finish();
}

}  // namespace varc::variants
