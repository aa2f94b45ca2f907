// SPDX-License-Identifier: Apache-2.0
// Prints diagnostics clang style: `path:line:col: error: message`, the source line, notes.
#include "varc/cli/DiagnosticPrinter.h"

#include <ostream>
#include <string>

namespace varc::cli {

namespace {

void printHeader(SourceLocation location, Severity severity, const std::string& message,
                 const includes::SourceMap& sourceMap, std::ostream& err) {
    if (location.isKnown()) {
        err << sourceMap.format(location) << ": ";
    } else {
        err << "varc: ";
    }
    err << severityName(severity) << ": " << message << "\n";
}

// The offending source line and a caret under the column, when both are known. Tabs in the
// prefix are kept so the caret lines up in a terminal.
void printSourceLine(SourceLocation location, const includes::SourceMap& sourceMap,
                     std::ostream& err) {
    if (!location.isKnown() || location.line == 0 || location.column == 0) return;
    std::string line = sourceMap.lineText(location.file, location.line);
    if (line.empty() || location.column > line.size() + 1) return;
    std::string caret;
    for (size_t i = 0; i + 1 < location.column; ++i) caret += line[i] == '\t' ? '\t' : ' ';
    err << line << "\n" << caret << "^\n";
}

}  // namespace

void printDiagnostics(const std::vector<Diagnostic>& diagnostics,
                      const includes::SourceMap& sourceMap, std::ostream& err) {
    size_t errors = 0;
    for (const Diagnostic& diagnostic : diagnostics) {
        if (diagnostic.severity == Severity::Error) ++errors;
        printHeader(diagnostic.location, diagnostic.severity, diagnostic.message, sourceMap, err);
        printSourceLine(diagnostic.location, sourceMap, err);
        for (const DiagnosticNote& note : diagnostic.notes) {
            printHeader(note.location, Severity::Note, note.message, sourceMap, err);
        }
    }
    if (errors > 0) {
        err << errors << (errors == 1 ? " error" : " errors") << " generated.\n";
    }
}

}  // namespace varc::cli
