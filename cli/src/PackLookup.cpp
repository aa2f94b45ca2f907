// SPDX-License-Identifier: Apache-2.0
// `varc lookup`: the variant a runtime would pick for a keyword set or a light, and its programs.
#include <algorithm>
#include <nlohmann/json.hpp>
#include <ostream>

#include "OpenPack.h"
#include "varc/cli/PackCommands.h"
#include "varc/reader/PassView.h"
#include "varc/reader/ProgramView.h"
#include "varc/reader/ShaderView.h"
#include "varc/reader/VariantView.h"
#include "varc/variants/LightKeywords.h"
#include "varc/variants/VariantSelector.h"

namespace varc::cli {

namespace {

using Json = nlohmann::ordered_json;

bool isNumber(const std::string& text) {
    return !text.empty() &&
           std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// --pass N selects by the pass's index in its shader; anything else by LightMode.
std::optional<reader::PassView> findPass(const reader::ShaderView& shader,
                                         const std::string& selector) {
    if (!isNumber(selector)) return shader.pass(std::string_view(selector));
    for (size_t p = 0; p < shader.passCount(); ++p) {
        reader::PassView pass = *shader.pass(p);
        if (std::to_string(pass.index()) == selector) return pass;
    }
    return std::nullopt;
}

std::string passList(const reader::ShaderView& shader) {
    std::string text;
    for (size_t p = 0; p < shader.passCount(); ++p) {
        reader::PassView pass = *shader.pass(p);
        text += (text.empty() ? "" : ", ") + std::to_string(pass.index());
        if (!pass.lightMode().empty()) text += " (" + std::string(pass.lightMode()) + ")";
    }
    return text;
}

Json programJson(const reader::ProgramView& program) {
    return {
        {"program", program.index()},
        {"entry_point", program.entryPoint()},
        {"bytes", program.spirvByteSize()},
        {"source", std::string(program.sourceFile()) + ":" + std::to_string(program.sourceLine())}};
}

void printVariant(const reader::VariantView& variant, const std::vector<std::string>& requested,
                  bool json, std::ostream& out) {
    Json stages = Json::object();
    for (Stage stage : kStages) {
        if (auto program = variant.program(stage)) {
            stages[stageName(program->stage())] = programJson(*program);
        }
    }
    if (json) {
        out << Json{{"variant", variant.describe()},
                    {"requested", requested},
                    {"keywords", variant.keywords()},
                    {"exact", variant.exact()},
                    {"enumeration_index", variant.enumerationIndex()},
                    {"stages", stages}}
                   .dump()
            << "\n";
        return;
    }
    out << variant.describe() << (variant.exact() ? ": exact match" : ": nearest match") << "\n";
    for (const auto& [stage, program] : stages.items()) {
        out << "  " << stage << ": program " << program["program"].get<uint32_t>() << " ("
            << program["entry_point"].get<std::string>() << ", " << program["bytes"].get<size_t>()
            << " bytes) from " << program["source"].get<std::string>() << "\n";
    }
}

}  // namespace

int runLookup(const LookupOptions& options, std::ostream& out, std::ostream& err) {
    std::optional<reader::Pack> pack = openPackOrReport(options.packPath, err);
    if (!pack) return kExitUsage;
    std::optional<reader::ShaderView> shader = pack->findShader(options.shader);
    if (!shader) {
        err << "varc: error: " << options.packPath << ": no shader named \"" << options.shader
            << "\"\n";
        return kExitFailure;
    }
    std::optional<reader::PassView> pass = findPass(*shader, options.pass);
    if (!pass) {
        err << "varc: error: shader \"" << options.shader << "\" has no pass '" << options.pass
            << "'; its passes: " << passList(*shader) << "\n";
        return kExitFailure;
    }
    std::vector<std::string> keywords = options.keywords;
    Result<reader::VariantView> variant = makeError(ErrorCode::Internal, "no lookup");
    if (options.light) {
        variant = pass->lookup(*options.light, options.policy, pass->keyOf(keywords));
        // Report what was asked: the light's keywords for this pass plus the material's.
        if (auto kind = variants::lightPassKindFromLightMode(pass->lightMode())) {
            for (std::string& keyword : variants::lightKeywords(*options.light, *kind))
                keywords.push_back(keyword);
            std::sort(keywords.begin(), keywords.end());
        }
    } else {
        variant = pass->lookup(keywords, options.policy);
    }
    if (!variant) {
        err << "varc: error: " << variant.error().detail << "\n";
        return kExitFailure;
    }
    printVariant(*variant, keywords, options.json, out);
    return kExitOk;
}

}  // namespace varc::cli
