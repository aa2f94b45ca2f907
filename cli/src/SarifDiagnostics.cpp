// SPDX-License-Identifier: Apache-2.0
// Prints diagnostics as a SARIF 2.1.0 log (`--diagnostics-format sarif`), for code scanning.
#include "SarifDiagnostics.h"

#include <nlohmann/json.hpp>
#include <ostream>

#include "DiagnosticPaths.h"
#include "varc/driver/PackAssembler.h"

namespace varc::cli {

namespace {

using Json = nlohmann::ordered_json;

constexpr DiagnosticRule kRules[] = {DiagnosticRule::Input, DiagnosticRule::Compile,
                                     DiagnosticRule::Lock, DiagnosticRule::Tool};

Json driver() {
    Json rules = Json::array();
    for (DiagnosticRule rule : kRules) {
        rules.push_back(
            {{"id", ruleId(rule)}, {"shortDescription", {{"text", ruleDescription(rule)}}}});
    }
    return {{"name", "varc"},
            {"version", driver::toolchainVersions().front().version},
            {"rules", std::move(rules)}};
}

// A SARIF location: the physical location when |location| is known, and |message| if any.
Json sarifLocation(SourceLocation location, const std::string& message,
                   const includes::SourceMap& sourceMap) {
    Json result = Json::object();
    if (location.isKnown()) {
        Json physical = {{"artifactLocation", {{"uri", pathUri(sourceMap.path(location.file))}}}};
        if (location.line > 0) {
            physical["region"] = {{"startLine", location.line}};
            if (location.column > 0) physical["region"]["startColumn"] = location.column;
        }
        result["physicalLocation"] = std::move(physical);
    }
    if (!message.empty()) result["message"] = {{"text", message}};
    return result;
}

Json sarifResult(const RuledDiagnostic& ruled, const includes::SourceMap& sourceMap) {
    const Diagnostic& diagnostic = ruled.diagnostic;
    size_t ruleIndex = 0;
    while (kRules[ruleIndex] != ruled.rule) ++ruleIndex;
    Json result = {{"ruleId", ruleId(ruled.rule)},
                   {"ruleIndex", ruleIndex},
                   {"level", severityName(diagnostic.severity)},
                   {"message", {{"text", diagnostic.message}}}};
    if (diagnostic.location.isKnown()) {
        result["locations"] = Json::array({sarifLocation(diagnostic.location, "", sourceMap)});
    }
    if (!diagnostic.notes.empty()) {
        Json related = Json::array();
        int id = 0;
        for (const DiagnosticNote& note : diagnostic.notes) {
            Json location = sarifLocation(note.location, note.message, sourceMap);
            location["id"] = id++;
            related.push_back(std::move(location));
        }
        result["relatedLocations"] = std::move(related);
    }
    return result;
}

}  // namespace

void printSarifDiagnostics(const std::vector<RuledDiagnostic>& diagnostics,
                           const includes::SourceMap& sourceMap, std::ostream& err) {
    Json results = Json::array();
    for (const RuledDiagnostic& ruled : diagnostics) {
        results.push_back(sarifResult(ruled, sourceMap));
    }
    Json run = {{"tool", {{"driver", driver()}}}, {"results", std::move(results)}};
    Json log = {{"$schema", "https://json.schemastore.org/sarif-2.1.0.json"},
                {"version", "2.1.0"},
                {"runs", Json::array({std::move(run)})}};
    err << log.dump(2) << "\n";
}

}  // namespace varc::cli
