// SPDX-License-Identifier: Apache-2.0
// The include chain of a line of expanded source, read back from its `#line` directives.
#pragma once

#include <string>
#include <vector>

#include "varc/core/Diagnostic.h"
#include "varc/includes/SourceMap.h"

namespace varc::driver {

// Notes "in file included from here" for |file| in |expandedText| (IncludeResolver's output, with
// a `#line <line> <fileId>` at every switch between files), innermost first, each at the line of
// the #include that first brought the file in (column unknown). |root| is the file the program
// text itself comes from (its blocks start the chain afresh). The chain stops at a link whose
// line does not name the file it includes (a file with no line of its own before its #include
// leaves no #line behind, so the text cannot tell it was there). Empty for |root| or a file the
// text never enters. Example: a.shader (the root) includes b.h at line 4, which includes c.h at
// its line 2: for c.h -> {b.h:2 "in file included from here", a.shader:4 "..."}.
std::vector<DiagnosticNote> includeChainNotes(const std::string& expandedText, FileId root,
                                              FileId file, const includes::SourceMap& sourceMap);

// |diagnostics| with their includeChainNotes added before their own notes.
std::vector<Diagnostic> withIncludeChains(std::vector<Diagnostic> diagnostics,
                                          const std::string& expandedText, FileId root,
                                          const includes::SourceMap& sourceMap);

}  // namespace varc::driver
