// SPDX-License-Identifier: Apache-2.0
// User-facing problems in shader source, keywords or command lines (error tier 1).
#pragma once

#include <string>
#include <vector>

#include "varc/core/SourceLocation.h"

namespace varc {

enum class Severity { Note, Warning, Error };

// "note", "warning" or "error", as compilers print it.
const char* severityName(Severity severity);

// A note attached to a diagnostic, e.g. "in file included from a.shader:12:1".
struct DiagnosticNote {
    SourceLocation location;
    std::string message;
};

// One problem found in user input. Libraries report these to a DiagnosticSink and never print;
// only the CLI renders them, clang style: `path:line:col: error: message`.
struct Diagnostic {
    Severity severity = Severity::Error;
    SourceLocation location;
    std::string message;
    std::vector<DiagnosticNote> notes;
};

// Receives diagnostics. Passed explicitly to every function that can report one.
class DiagnosticSink {
public:
    virtual ~DiagnosticSink() = default;
    virtual void report(Diagnostic diagnostic) = 0;

    // Convenience for the common case of an error without notes.
    void error(SourceLocation location, std::string message) {
        report({Severity::Error, location, std::move(message), {}});
    }
    void warning(SourceLocation location, std::string message) {
        report({Severity::Warning, location, std::move(message), {}});
    }
};

// Collects diagnostics in a vector; used by the CLI and by tests.
class DiagnosticList final : public DiagnosticSink {
public:
    void report(Diagnostic diagnostic) override { mDiagnostics.push_back(std::move(diagnostic)); }

    const std::vector<Diagnostic>& diagnostics() const { return mDiagnostics; }
    size_t errorCount() const;
    bool hasErrors() const { return errorCount() > 0; }
    void clear() { mDiagnostics.clear(); }

private:
    std::vector<Diagnostic> mDiagnostics;
};

}  // namespace varc
