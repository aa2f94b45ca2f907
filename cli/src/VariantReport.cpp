// SPDX-License-Identifier: Apache-2.0
// The output of `varc variants`: a text listing in the spirit of Unity's "Show variants", or JSON.
#include "varc/cli/VariantReport.h"

#include <ostream>

#include "varc/core/JoinWords.h"
#include "varc/core/KeywordNames.h"
#include "varc/core/SaturatingMath.h"

namespace varc::cli {

namespace {

using Json = nlohmann::ordered_json;

// null for the shader's own passes; {"kind": "fallback"|"usepass", "shader": name} otherwise
// (the JSON lists "from" for borrowed passes only).
Json passOriginJson(const shaderlab::PassOrigin& origin) {
    switch (origin.kind) {
        case shaderlab::PassOrigin::Kind::Own:
            return nullptr;
        case shaderlab::PassOrigin::Kind::UsePass:
            return {{"kind", "usepass"}, {"shader", origin.shader}};
        case shaderlab::PassOrigin::Kind::Fallback:
            return {{"kind", "fallback"}, {"shader", origin.shader}};
    }
    return nullptr;
}

}  // namespace

Json stagesJson(const frontend::VariantStageCounts& counts) {
    return {{"declared", counts.declared},
            {"materials", counts.materials},
            {"settings", counts.settings},
            {"rules", counts.rules}};
}

std::string stagesText(const frontend::VariantStageCounts& counts) {
    return "declared " + std::to_string(counts.declared) + " -> materials " +
           std::to_string(counts.materials) + " -> settings " + std::to_string(counts.settings) +
           " -> rules " + std::to_string(counts.rules);
}

namespace {

Json passJson(const frontend::LoadedPass& pass, bool withList) {
    Json sets = Json::array();
    for (const variants::KeywordSetDecl& set : pass.keywords.sets)
        sets.push_back(displayKeywords(set.keywords));
    Json json = {{"index", pass.index},
                 {"name", pass.pass->name},
                 {"lightmode", pass.pass->lightMode()},
                 {"keyword_sets", sets},
                 {"variants", pass.variantCount()}};
    if (pass.plan) json["stages"] = stagesJson(pass.plan->counts);
    Json origin = passOriginJson(pass.pass->origin);
    if (!origin.is_null()) json["from"] = std::move(origin);
    if (withList) {
        Json list = Json::array();
        pass.forEachVariant([&](const variants::VariantKey& key) {
            list.push_back(pass.space->table().namesOf(key));
            return true;
        });
        json["list"] = std::move(list);
    }
    return json;
}

void printVariantList(const frontend::LoadedPass& pass, std::ostream& out) {
    out << "      " << pass.variantCount() << " keyword variants:\n";
    pass.forEachVariant([&](const variants::VariantKey& key) {
        std::vector<std::string> names = pass.space->table().namesOf(key);
        // Unity's inspector spelling for the variant without keywords, kept for familiarity.
        out << "        " << (names.empty() ? "<no keywords defined>" : joinWords(names)) << "\n";
        return true;
    });
}

void printPass(const frontend::LoadedPass& pass, const includes::SourceMap& sourceMap,
               bool withList, std::ostream& out) {
    out << "  pass " << pass.index;
    if (!pass.pass->name.empty()) out << " \"" << pass.pass->name << "\"";
    std::string lightMode = pass.pass->lightMode();
    if (!lightMode.empty()) out << " LightMode " << lightMode;
    std::string origin = frontend::describePassOrigin(pass.pass->origin);
    if (!origin.empty()) {
        out << " (" << origin << ", "
            << sourceMap.format(
                   {pass.pass->origin.reference.file, pass.pass->origin.reference.line, 0})
            << ")";
    }
    uint64_t count = pass.variantCount();
    out << ": " << count << (count == 1 ? " variant" : " variants");
    uint64_t declared = pass.space->count(), full = pass.space->fullCount();
    if (pass.plan) out << " (" << stagesText(pass.plan->counts) << ")";
    if (full != declared) out << " (of " << full << " before skip_variants and shortcut rules)";
    out << "\n";
    for (const variants::KeywordSetDecl& set : pass.keywords.sets) {
        out << "      " << set.directive << ": " << joinWords(displayKeywords(set.keywords))
            << "  (" << sourceMap.format({set.location.file, set.location.line, 0}) << ")\n";
    }
    if (!pass.keywords.skipped.empty()) {
        out << "      skip_variants: " << joinWords(pass.keywords.skipped) << "\n";
    }
    if (withList) printVariantList(pass, out);
}

}  // namespace

Json variantsJson(const std::vector<frontend::LoadedShader>& shaders, bool withList) {
    Json shaderArray = Json::array();
    uint64_t total = 0;
    for (const frontend::LoadedShader& shader : shaders) {
        Json passes = Json::array();
        for (const frontend::LoadedPass& pass : shader.passes)
            passes.push_back(passJson(pass, withList));
        uint64_t count = shader.variantCount();
        total = saturatingAdd(total, count);
        shaderArray.push_back({{"file", shader.path},
                               {"name", shader.ast.name},
                               {"passes", passes},
                               {"variants", count}});
    }
    return {{"shaders", shaderArray}, {"variants", total}};
}

void printVariantsText(const std::vector<frontend::LoadedShader>& shaders,
                       const includes::SourceMap& sourceMap, bool withList, std::ostream& out) {
    uint64_t total = 0;
    for (const frontend::LoadedShader& shader : shaders) {
        out << "Shader \"" << shader.ast.name << "\" (" << shader.path << ")\n";
        if (shader.passes.empty()) out << "  no program passes\n";
        for (const frontend::LoadedPass& pass : shader.passes)
            printPass(pass, sourceMap, withList, out);
        uint64_t count = shader.variantCount();
        total = saturatingAdd(total, count);
        out << "  " << count << " variants total\n\n";
    }
    out << total << " variants in " << shaders.size()
        << (shaders.size() == 1 ? " shader" : " shaders") << "\n";
}

}  // namespace varc::cli
