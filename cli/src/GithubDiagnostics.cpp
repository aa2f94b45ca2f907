// SPDX-License-Identifier: Apache-2.0
// Prints diagnostics as GitHub Actions workflow commands (`::error file=F,line=L,col=C::MSG`).
#include "GithubDiagnostics.h"

#include <ostream>
#include <string>

#include "DiagnosticPaths.h"

namespace varc::cli {

namespace {

// GitHub's command for |severity|: "notice" for a note, else the severity's name.
const char* commandName(Severity severity) {
    return severity == Severity::Note ? "notice" : severityName(severity);
}

// GitHub's escaping of a command's message; properties also escape ':' and ','.
std::string escape(const std::string& text, bool property) {
    std::string result;
    for (char c : text) {
        switch (c) {
            case '%':
                result += "%25";
                break;
            case '\r':
                result += "%0D";
                break;
            case '\n':
                result += "%0A";
                break;
            case ':':
                result += property ? "%3A" : ":";
                break;
            case ',':
                result += property ? "%2C" : ",";
                break;
            default:
                result += c;
        }
    }
    return result;
}

std::string properties(SourceLocation location, const includes::SourceMap& sourceMap) {
    if (!location.isKnown()) return "";
    std::string text = "file=" + escape(pathForCi(sourceMap.path(location.file)), true);
    if (location.line > 0) text += ",line=" + std::to_string(location.line);
    if (location.line > 0 && location.column > 0) text += ",col=" + std::to_string(location.column);
    return text;
}

std::string noteLine(const DiagnosticNote& note, const includes::SourceMap& sourceMap) {
    std::string where = formatForCi(note.location, sourceMap);
    return (where.empty() ? "" : where + ": ") + "note: " + note.message;
}

}  // namespace

void printGithubDiagnostics(const std::vector<Diagnostic>& diagnostics,
                            const includes::SourceMap& sourceMap, std::ostream& err) {
    for (const Diagnostic& diagnostic : diagnostics) {
        std::string message = diagnostic.message;
        for (const DiagnosticNote& note : diagnostic.notes) {
            message += "\n" + noteLine(note, sourceMap);
        }
        std::string props = properties(diagnostic.location, sourceMap);
        err << "::" << commandName(diagnostic.severity) << (props.empty() ? "" : " ") << props
            << "::" << escape(message, false) << "\n";
    }
}

}  // namespace varc::cli
