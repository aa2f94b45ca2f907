// SPDX-License-Identifier: Apache-2.0
// Writes a command's diagnostics to standard error in the format `--diagnostics-format` chose.
#include "varc/cli/DiagnosticOutput.h"

#include <ostream>

#include "GithubDiagnostics.h"
#include "JsonDiagnostics.h"
#include "SarifDiagnostics.h"
#include "varc/cli/DiagnosticPrinter.h"

namespace varc::cli {

const char* ruleId(DiagnosticRule rule) {
    switch (rule) {
        case DiagnosticRule::Input:
            return "varc.input";
        case DiagnosticRule::Compile:
            return "varc.compile";
        case DiagnosticRule::Lock:
            return "varc.lock";
        case DiagnosticRule::Tool:
            return "varc.tool";
    }
    return "varc.tool";
}

const char* ruleDescription(DiagnosticRule rule) {
    switch (rule) {
        case DiagnosticRule::Input:
            return "Shader input: reading, ShaderLab, includes, pragmas and keyword sets";
        case DiagnosticRule::Compile:
            return "Compiling a variant's programs to SPIR-V";
        case DiagnosticRule::Lock:
            return "Variant counts against the lock file (varc check)";
        case DiagnosticRule::Tool:
            return "The command itself: files it cannot read or write";
    }
    return "";
}

DiagnosticOutput::DiagnosticOutput(DiagnosticsFormat format, const includes::SourceMap& sourceMap,
                                   std::ostream& err)
    : mFormat(format), mSourceMap(sourceMap), mErr(err) {}

bool DiagnosticOutput::isDocument() const {
    return mFormat == DiagnosticsFormat::Json || mFormat == DiagnosticsFormat::Sarif;
}

void DiagnosticOutput::print(const std::vector<Diagnostic>& diagnostics, DiagnosticRule rule) {
    switch (mFormat) {
        case DiagnosticsFormat::Clang:
            printDiagnostics(diagnostics, mSourceMap, mErr);
            return;
        case DiagnosticsFormat::Github:
            printGithubDiagnostics(diagnostics, mSourceMap, mErr);
            return;
        case DiagnosticsFormat::Json:
        case DiagnosticsFormat::Sarif:
            for (const Diagnostic& diagnostic : diagnostics) {
                mCollected.push_back({rule, diagnostic});
            }
            return;
    }
}

void DiagnosticOutput::error(const std::string& message, DiagnosticRule rule) {
    if (mFormat == DiagnosticsFormat::Clang) {
        mErr << "varc: error: " << message << "\n";
        return;
    }
    print({Diagnostic{Severity::Error, {}, message, {}}}, rule);
}

void DiagnosticOutput::summary(const std::string& line) {
    if (!isDocument()) mErr << line << "\n";
}

void DiagnosticOutput::finish() {
    if (mFormat == DiagnosticsFormat::Json) {
        printJsonDiagnostics(mCollected, mSourceMap, mErr);
    } else if (mFormat == DiagnosticsFormat::Sarif) {
        printSarifDiagnostics(mCollected, mSourceMap, mErr);
    }
}

}  // namespace varc::cli
