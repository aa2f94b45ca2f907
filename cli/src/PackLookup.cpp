// SPDX-License-Identifier: Apache-2.0
// `varc lookup`: the variant a runtime would pick for a keyword set or a light, and its programs.
#include <algorithm>
#include <nlohmann/json.hpp>
#include <ostream>
#include <sstream>

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

std::vector<std::string> splitWords(const std::string& text) {
    std::vector<std::string> words;
    std::istringstream stream(text);
    for (std::string word; stream >> word;) words.push_back(word);
    return words;
}

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

// The light described on the command line; nullopt after printing a usage error.
std::optional<variants::LightDescription> lightFromOptions(const Options& options,
                                                           std::ostream& err) {
    variants::LightDescription light;
    auto type = variants::parseLightType(options.lookupLight);
    if (!type) {
        err << "varc: error: --light expects directional, point or spot, got '"
            << options.lookupLight << "'\n";
        return std::nullopt;
    }
    auto shadows = variants::parseShadowMode(options.lookupShadows);
    if (!shadows) {
        err << "varc: error: --shadows expects none, hard or soft, got '" << options.lookupShadows
            << "'\n";
        return std::nullopt;
    }
    light.type = *type;
    light.shadows = *shadows;
    light.cookie = options.lookupCookie;
    light.vertexLightCount = options.lookupVertexLights;
    light.hdr = options.lookupHdr;
    return light;
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

int runLookup(const Options& options, std::ostream& out, std::ostream& err) {
    std::optional<reader::Pack> pack = openPackOrReport(options.packPath, err);
    if (!pack) return kExitUsage;
    std::optional<reader::ShaderView> shader = pack->findShader(options.lookupShader);
    if (!shader) {
        err << "varc: error: " << options.packPath << ": no shader named \"" << options.lookupShader
            << "\"\n";
        return kExitFailure;
    }
    std::optional<reader::PassView> pass = findPass(*shader, options.lookupPass);
    if (!pass) {
        err << "varc: error: shader \"" << options.lookupShader << "\" has no pass '"
            << options.lookupPass << "'; its passes: " << passList(*shader) << "\n";
        return kExitFailure;
    }
    auto policy = variants::parseSelectionPolicy(options.lookupPolicy);
    if (!policy) {
        err << "varc: error: --policy expects exact, closest, first or strict, got '"
            << options.lookupPolicy << "'\n";
        return kExitUsage;
    }
    std::vector<std::string> keywords = splitWords(options.lookupKeywords);
    Result<reader::VariantView> variant = makeError(ErrorCode::Internal, "no lookup");
    if (!options.lookupLight.empty()) {
        std::optional<variants::LightDescription> light = lightFromOptions(options, err);
        if (!light) return kExitUsage;
        variant = pass->lookup(*light, *policy, pass->keyOf(keywords));
        // Report what was asked: the light's keywords for this pass plus the material's.
        if (auto kind = variants::lightPassKindFromLightMode(pass->lightMode())) {
            for (std::string& keyword : variants::lightKeywords(*light, *kind))
                keywords.push_back(keyword);
            std::sort(keywords.begin(), keywords.end());
        }
    } else {
        variant = pass->lookup(keywords, *policy);
    }
    if (!variant) {
        err << "varc: error: " << variant.error().detail << "\n";
        return kExitFailure;
    }
    printVariant(*variant, keywords, options.json, out);
    return kExitOk;
}

}  // namespace varc::cli
