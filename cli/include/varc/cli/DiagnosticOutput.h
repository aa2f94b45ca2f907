// SPDX-License-Identifier: Apache-2.0
// Writes a command's diagnostics to standard error in the format `--diagnostics-format` chose.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include "varc/cli/Options.h"
#include "varc/core/Diagnostic.h"
#include "varc/includes/SourceMap.h"

namespace varc::cli {

// What kind of check found a problem: SARIF's rule, JSON's "rule". Clang and GitHub output do
// not show it.
enum class DiagnosticRule { Input, Compile, Lock, Tool };

// The rule's id ("varc.input", "varc.compile", "varc.lock", "varc.tool") and a one-line
// description of what it checks.
const char* ruleId(DiagnosticRule rule);
const char* ruleDescription(DiagnosticRule rule);

// A diagnostic and the rule that reported it, as the document formats collect them.
struct RuledDiagnostic {
    DiagnosticRule rule = DiagnosticRule::Input;
    Diagnostic diagnostic;
};

// One per command run. Clang and GitHub output are written as diagnostics arrive (clang style is
// byte for byte what printDiagnostics writes); JSON and SARIF are one document each, written by
// finish(), so standard error holds nothing else in those formats.
class DiagnosticOutput {
public:
    DiagnosticOutput(DiagnosticsFormat format, const includes::SourceMap& sourceMap,
                     std::ostream& err);

    // Reports |diagnostics| (every one of them, in order) as found by |rule|.
    void print(const std::vector<Diagnostic>& diagnostics, DiagnosticRule rule);
    // A problem with no source position, e.g. an unreadable lock file: "varc: error: MESSAGE"
    // in clang style.
    void error(const std::string& message, DiagnosticRule rule = DiagnosticRule::Tool);
    // A line for people that says how the run ended ("varc build: failed; ..."): written as is
    // in clang and GitHub output, left out of the JSON and SARIF documents.
    void summary(const std::string& line);
    // Writes the JSON or SARIF document (with every diagnostic reported, or none); nothing for
    // the streaming formats. Call once, at the end of the command.
    void finish();

    // Whether the format is a document that must own standard error (no progress lines).
    bool isDocument() const;

private:
    DiagnosticsFormat mFormat;
    const includes::SourceMap& mSourceMap;
    std::ostream& mErr;
    std::vector<RuledDiagnostic> mCollected;
};

}  // namespace varc::cli
