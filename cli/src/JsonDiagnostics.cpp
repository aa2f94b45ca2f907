// SPDX-License-Identifier: Apache-2.0
// Prints diagnostics as one JSON document (`--diagnostics-format json`).
#include "JsonDiagnostics.h"

#include <nlohmann/json.hpp>
#include <ostream>

#include "DiagnosticPaths.h"

namespace varc::cli {

namespace {

// "file", "line", "column" of |location| into |object|.
void addLocation(SourceLocation location, const includes::SourceMap& sourceMap,
                 nlohmann::ordered_json& object) {
    object["file"] = location.isKnown()
                         ? nlohmann::ordered_json(pathForCi(sourceMap.path(location.file)))
                         : nlohmann::ordered_json(nullptr);
    object["line"] = location.isKnown() ? location.line : 0;
    object["column"] = location.isKnown() ? location.column : 0;
}

}  // namespace

void printJsonDiagnostics(const std::vector<RuledDiagnostic>& diagnostics,
                          const includes::SourceMap& sourceMap, std::ostream& err) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    size_t errors = 0;
    size_t warnings = 0;
    for (const RuledDiagnostic& ruled : diagnostics) {
        const Diagnostic& diagnostic = ruled.diagnostic;
        errors += diagnostic.severity == Severity::Error ? 1 : 0;
        warnings += diagnostic.severity == Severity::Warning ? 1 : 0;
        nlohmann::ordered_json item;
        item["severity"] = severityName(diagnostic.severity);
        item["rule"] = ruleId(ruled.rule);
        addLocation(diagnostic.location, sourceMap, item);
        item["message"] = diagnostic.message;
        item["notes"] = nlohmann::ordered_json::array();
        for (const DiagnosticNote& note : diagnostic.notes) {
            nlohmann::ordered_json noteItem;
            addLocation(note.location, sourceMap, noteItem);
            noteItem["message"] = note.message;
            item["notes"].push_back(std::move(noteItem));
        }
        list.push_back(std::move(item));
    }
    nlohmann::ordered_json document;
    document["diagnostics"] = std::move(list);
    document["errors"] = errors;
    document["warnings"] = warnings;
    err << document.dump() << "\n";
}

}  // namespace varc::cli
