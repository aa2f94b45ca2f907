// SPDX-License-Identifier: Apache-2.0
// `varc info`: what a pack holds, per shader and pass, with distinct programs per stage.
#include <array>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <ostream>
#include <set>

#include "OpenPack.h"
#include "varc/cli/PackCommands.h"
#include "varc/core/HexText.h"
#include "varc/reader/PassView.h"
#include "varc/reader/ProgramView.h"
#include "varc/reader/ShaderView.h"
#include "varc/reader/VariantView.h"

namespace varc::cli {

namespace {

using Json = nlohmann::ordered_json;

// Distinct program indices per stage over every variant of |pass|.
std::array<std::set<uint32_t>, kStageCount> distinctPrograms(const reader::PassView& pass) {
    std::array<std::set<uint32_t>, kStageCount> programs;
    for (size_t v = 0; v < pass.variantCount(); ++v) {
        reader::VariantView variant = pass.variant(v);
        for (Stage stage : kStages) {
            if (auto program = variant.program(stage)) {
                programs[stageIndex(stage)].insert(program->index());
            }
        }
    }
    return programs;
}

Json programsJson(const reader::PassView& pass) {
    Json json = Json::object();
    auto programs = distinctPrograms(pass);
    for (Stage stage : kStages) {
        const std::set<uint32_t>& distinct = programs[stageIndex(stage)];
        if (!distinct.empty()) json[stageName(stage)] = distinct.size();
    }
    return json;
}

Json keywordSetsJson(const reader::PassView& pass) {
    Json sets = Json::array();
    for (size_t i = 0; i < pass.setCount(); ++i) {
        Json keywords = Json::array();
        for (const std::string& keyword : pass.set(i).keywords) {
            keywords.push_back(keyword.empty() ? "_" : keyword);
        }
        sets.push_back(std::move(keywords));
    }
    return sets;
}

uint64_t spirvBytes(const reader::Pack& pack) {
    uint64_t bytes = 0;
    for (size_t i = 0; i < pack.programCount(); ++i) bytes += pack.program(i).spirvByteSize();
    return bytes;
}

// |value| as the double whose shortest form equals the float's (0.1f prints as 0.1, not as
// 0.10000000149011612).
double shortest(float value) {
    char text[32];
    auto [end, error] = std::to_chars(text, text + sizeof(text), value);
    return error == std::errc() ? std::strtod(std::string(text, end).c_str(), nullptr) : value;
}

// The shader's Properties defaults: {"name", "kind", "default"}; default is a number, [x,y,z,w]
// or the texture's name.
Json propertiesJson(const reader::ShaderView& shader) {
    static const char* const kKinds[] = {"float", "vector", "color", "texture"};
    Json properties = Json::array();
    for (const pack::ShaderProperty& property : shader.properties()) {
        Json value;
        switch (property.kind) {
            case pack::PropertyKind::Float:
                value = shortest(property.value[0]);
                break;
            case pack::PropertyKind::Vector:
            case pack::PropertyKind::Color:
                value = Json::array();
                for (float component : property.value) value.push_back(shortest(component));
                break;
            case pack::PropertyKind::Texture:
                value = property.texture;
                break;
        }
        properties.push_back({{"name", property.name},
                              {"kind", kKinds[static_cast<size_t>(property.kind)]},
                              {"default", value}});
    }
    return properties;
}

Json infoJson(const reader::Pack& pack, const std::string& path) {
    Json shaders = Json::array();
    uint64_t total = 0;
    for (size_t s = 0; s < pack.shaderCount(); ++s) {
        reader::ShaderView shader = pack.shader(s);
        Json passes = Json::array();
        uint64_t shaderTotal = 0;
        for (size_t p = 0; p < shader.passCount(); ++p) {
            reader::PassView pass = *shader.pass(p);
            passes.push_back({{"index", pass.index()},
                              {"name", pass.name()},
                              {"lightmode", pass.lightMode()},
                              {"keyword_sets", keywordSetsJson(pass)},
                              {"variants", pass.variantCount()},
                              {"programs", programsJson(pass)}});
            shaderTotal += pass.variantCount();
        }
        shaders.push_back({{"name", shader.name()},
                           {"passes", passes},
                           {"variants", shaderTotal},
                           {"properties", propertiesJson(shader)}});
        total += shaderTotal;
    }
    Json toolchain = Json::object();
    for (const pack::ToolVersion& tool : pack.toolchain()) toolchain[tool.name] = tool.version;
    return {
        {"file", path},
        {"format", std::to_string(pack.formatMajor()) + "." + std::to_string(pack.formatMinor())},
        {"inputs_hash", hex64(pack.inputsHash())},
        {"toolchain", toolchain},
        {"shaders", shaders},
        {"variants", total},
        {"programs", pack.programCount()},
        {"bytes", {{"spirv", spirvBytes(pack)}, {"pack", pack.byteSize()}}}};
}

std::string stageCounts(const Json& programs) {
    std::string text;
    for (const auto& [stage, count] : programs.items()) {
        text += (text.empty() ? "" : ", ") + stage + " " + std::to_string(count.get<size_t>());
    }
    return text;
}

void printInfoText(const Json& info, std::ostream& out) {
    out << "Pack " << info["file"].get<std::string>() << ": format "
        << info["format"].get<std::string>() << ", " << info["bytes"]["pack"].get<uint64_t>()
        << " bytes (" << info["bytes"]["spirv"].get<uint64_t>() << " bytes of SPIR-V in "
        << info["programs"].get<size_t>() << " programs), inputs hash "
        << info["inputs_hash"].get<std::string>() << "\n  built with";
    for (const auto& [tool, version] : info["toolchain"].items()) {
        out << " " << tool << " " << version.get<std::string>();
    }
    out << "\n";
    for (const Json& shader : info["shaders"]) {
        out << "Shader \"" << shader["name"].get<std::string>() << "\"\n";
        for (const Json& pass : shader["passes"]) {
            out << "  pass " << pass["index"].get<uint32_t>();
            if (!pass["name"].get<std::string>().empty())
                out << " \"" << pass["name"].get<std::string>() << "\"";
            if (!pass["lightmode"].get<std::string>().empty()) {
                out << " LightMode " << pass["lightmode"].get<std::string>();
            }
            uint64_t variants = pass["variants"].get<uint64_t>();
            out << ": " << variants << (variants == 1 ? " variant" : " variants") << "; programs "
                << stageCounts(pass["programs"]) << "\n";
        }
    }
    size_t shaders = info["shaders"].size();
    out << info["variants"].get<uint64_t>() << " variants in " << shaders
        << (shaders == 1 ? " shader\n" : " shaders\n");
}

}  // namespace

int runInfo(const InfoOptions& options, std::ostream& out, std::ostream& err) {
    std::optional<reader::Pack> pack = openPackOrReport(options.packPath, err);
    if (!pack) return kExitUsage;
    Json info = infoJson(*pack, options.packPath);
    if (options.json) {
        out << info.dump() << "\n";
    } else {
        printInfoText(info, out);
    }
    return kExitOk;
}

}  // namespace varc::cli
