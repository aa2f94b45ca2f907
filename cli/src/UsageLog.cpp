// SPDX-License-Identifier: Apache-2.0
// Reading the runtime's usage log and turning its entries into per-pass collection requests.
#include "UsageLog.h"

#include <nlohmann/json.hpp>
#include <sstream>

#include "varc/core/FileRead.h"

namespace varc::cli {

namespace {

using Json = nlohmann::json;

// One entry from |json|, or an error message.
std::optional<UsageEntry> entryOf(const Json& json, std::string& error) {
    if (!json.is_object()) {
        error = "expected an object {\"shader\", \"pass\", \"lightmode\", \"keywords\"}";
        return std::nullopt;
    }
    auto shader = json.find("shader"), pass = json.find("pass"), lightMode = json.find("lightmode"),
         keywords = json.find("keywords");
    if (shader == json.end() || !shader->is_string() || pass == json.end() ||
        !pass->is_number_unsigned() || lightMode == json.end() || !lightMode->is_string() ||
        keywords == json.end() || !keywords->is_array()) {
        error = "expected \"shader\" (string), \"pass\" (number), \"lightmode\" (string) and "
                "\"keywords\" (list)";
        return std::nullopt;
    }
    UsageEntry entry{shader->get<std::string>(), pass->get<size_t>(),
                     lightMode->get<std::string>(), {}, {}};
    for (const Json& keyword : *keywords) {
        if (!keyword.is_string()) {
            error = "\"keywords\" holds a value that is not a string";
            return std::nullopt;
        }
        entry.keywords.push_back(keyword.get<std::string>());
    }
    return entry;
}

}  // namespace

std::optional<std::vector<UsageEntry>> readUsageLog(const std::string& path,
                                                    includes::SourceMap& sourceMap,
                                                    DiagnosticSink& sink) {
    Result<std::string> text = readFile(path, size_t{1} << 28);
    if (!text) {
        sink.error({}, "cannot read usage log '" + path + "': " + text.error().detail);
        return std::nullopt;
    }
    FileId file = sourceMap.addFile(path, *text);
    std::istringstream lines(*text);
    std::vector<UsageEntry> entries;
    bool ok = true;
    std::string line;
    for (uint32_t number = 1; std::getline(lines, line); ++number) {
        SourceLocation where{file, number, 0};
        Json json = Json::parse(line, nullptr, /*allow_exceptions=*/false);
        if (number == 1) {
            if (json.is_discarded() || !json.is_object() || json.value("varc_usage_log", 0) != 1) {
                sink.error(where, "not a varc usage log: the first line must be "
                                  "{\"varc_usage_log\":1}");
                return std::nullopt;
            }
            continue;
        }
        if (line.empty()) continue;
        std::string error = json.is_discarded() ? "not JSON" : "";
        std::optional<UsageEntry> entry = error.empty() ? entryOf(json, error) : std::nullopt;
        if (!entry) {
            sink.error(where, "malformed usage log entry: " + error);
            ok = false;
            continue;
        }
        entry->location = where;
        entries.push_back(std::move(*entry));
    }
    if (!ok) return std::nullopt;
    return entries;
}

void addUsageDemands(const std::vector<UsageEntry>& entries,
                     const std::vector<frontend::LoadedShader>& shaders, ProjectInputs& inputs,
                     DiagnosticSink& sink) {
    for (const UsageEntry& entry : entries) {
        bool found = false;
        for (const frontend::LoadedShader& shader : shaders) {
            if (shader.ast.name != entry.shader) continue;
            for (const frontend::LoadedPass& pass : shader.passes) {
                if (pass.index != entry.pass) continue;
                found = true;
                inputs.demands[shader.path].collectionRequests.push_back(
                    {frontend::passTypeOfLightMode(pass.pass->lightMode()),
                     {variants::RequestKind::CollectionVariant, "the usage log", entry.keywords}});
            }
        }
        if (!found) {
            sink.report({Severity::Warning, entry.location,
                         "the usage log names pass " + std::to_string(entry.pass) +
                             " of shader \"" + entry.shader + "\", which the inputs do not have",
                         {}});
        }
    }
}

}  // namespace varc::cli
