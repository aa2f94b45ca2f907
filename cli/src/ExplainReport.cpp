// SPDX-License-Identifier: Apache-2.0
// `varc explain`: why a pass's variants exist and which keywords change which stage's program.
#include "varc/cli/ExplainReport.h"

#include <map>

#include "LineDiff.h"
#include "varc/variants/Shortcuts.h"

namespace varc::cli {

namespace {

using Json = nlohmann::ordered_json;

bool isShortcut(const std::string& directive) {
    const std::string prefix = "multi_compile_";
    return directive.rfind(prefix, 0) == 0 &&
           variants::findShortcut(std::string_view(directive).substr(prefix.size())) != nullptr;
}

Json stageNames(StageMask mask) {
    Json names = Json::array();
    for (Stage stage : kStages) {
        if (hasStage(mask, stage)) names.push_back(stageName(stage));
    }
    return names;
}

// The stages the pass compiles (those with a program in its first variant).
std::vector<Stage> passStages(const driver::CompiledPass& compiled) {
    std::vector<Stage> stages;
    if (compiled.variants.empty()) return stages;
    for (Stage stage : kStages) {
        if (compiled.variants.front().programs[stageIndex(stage)] != pack::kNoProgram) {
            stages.push_back(stage);
        }
    }
    return stages;
}

Json keywordsOf(const frontend::LoadedPass& pass, const variants::VariantKey& key) {
    return pass.space->table().namesOf(key);
}

Json setsJson(const ExplainRequest& request, const includes::SourceMap& sourceMap) {
    Json sets = Json::array();
    const auto& decls = request.pass->keywords.sets;
    for (size_t i = 0; i < decls.size(); ++i) {
        Json keywords = Json::array();
        for (const std::string& keyword : decls[i].keywords)
            keywords.push_back(keyword.empty() ? "_" : keyword);
        StageMask effects =
            i < request.compiled->setStageEffects.size() ? request.compiled->setStageEffects[i] : 0;
        sets.push_back({{"directive", decls[i].directive},
                        {"shortcut", isShortcut(decls[i].directive)},
                        {"location", sourceMap.format(decls[i].location)},
                        {"keywords", std::move(keywords)},
                        {"stages", stageNames(effects)}});
    }
    return sets;
}

Json stagesJson(const ExplainRequest& request) {
    Json stages = Json::array();
    const auto& variants = request.compiled->variants;
    for (Stage stage : passStages(*request.compiled)) {
        std::map<uint32_t, Json> byProgram;  // program id -> its variants
        std::vector<uint32_t> order;
        for (size_t v = 0; v < variants.size(); ++v) {
            uint32_t program = variants[v].programs[stageIndex(stage)];
            if (byProgram.find(program) == byProgram.end()) order.push_back(program);
            byProgram[program].push_back(
                {{"index", v}, {"keywords", keywordsOf(*request.pass, variants[v].key)}});
        }
        Json programs = Json::array();
        for (uint32_t program : order) {
            programs.push_back({{"program", program}, {"variants", std::move(byProgram[program])}});
        }
        stages.push_back({{"stage", stageName(stage)}, {"programs", std::move(programs)}});
    }
    return stages;
}

// Per set: the index of the option |key| takes (an option's keywords all on; the empty option
// when none is), or nullopt.
std::vector<std::optional<size_t>> choicesOf(const frontend::LoadedPass& pass,
                                             const variants::VariantKey& key) {
    std::vector<std::optional<size_t>> choices;
    for (const std::vector<variants::VariantKey>& options : pass.space->setOptions()) {
        std::optional<size_t> choice;
        for (size_t o = 0; o < options.size() && !choice; ++o) {
            if (!options[o].empty() && (key & options[o]) == options[o]) choice = o;
        }
        for (size_t o = 0; o < options.size() && !choice; ++o) {
            if (options[o].empty()) choice = o;
        }
        choices.push_back(choice);
    }
    return choices;
}

// The stages whose program differs between variants |a| and |b|.
Json differingStages(const driver::CompiledPass& compiled, size_t a, size_t b) {
    StageMask mask = 0;
    for (Stage stage : kStages) {
        if (compiled.variants[a].programs[stageIndex(stage)] !=
            compiled.variants[b].programs[stageIndex(stage)]) {
            mask |= stageBit(stage);
        }
    }
    return stageNames(mask);
}

Json nearestJson(const ExplainRequest& request, size_t variant) {
    const frontend::LoadedPass& pass = *request.pass;
    const auto& variants = request.compiled->variants;
    std::map<variants::VariantKey, size_t> indexOf;
    for (size_t v = 0; v < variants.size(); ++v) indexOf[variants[v].key] = v;
    const variants::VariantKey& key = variants[variant].key;
    std::vector<std::optional<size_t>> choices = choicesOf(pass, key);
    std::map<size_t, Json> nearest;  // by enumeration index
    for (size_t s = 0; s < choices.size(); ++s) {
        if (!choices[s]) continue;
        const auto& options = pass.space->setOptions()[s];
        variants::VariantKey without = key;
        const variants::VariantKey& current = options[*choices[s]];
        for (size_t bit = 0; bit < pass.space->table().size(); ++bit)
            if (current.test(bit)) without.reset(bit);
        for (size_t o = 0; o < options.size(); ++o) {
            if (o == *choices[s]) continue;
            auto it = indexOf.find(without | options[o]);
            if (it == indexOf.end()) continue;
            nearest[it->second] = {
                {"index", it->second},
                {"keywords", keywordsOf(pass, it->first)},
                {"set", s},
                {"differs_in", differingStages(*request.compiled, variant, it->second)}};
        }
    }
    Json list = Json::array();
    for (auto& [index, item] : nearest) list.push_back(std::move(item));
    return list;
}

Json variantJson(const ExplainRequest& request, size_t variant,
                 const includes::SourceMap& sourceMap) {
    const frontend::LoadedPass& pass = *request.pass;
    const pack::PackVariant& chosen = request.compiled->variants[variant];
    Json origins = Json::array();
    std::vector<std::optional<size_t>> choices = choicesOf(pass, chosen.key);
    for (size_t s = 0; s < choices.size(); ++s) {
        const variants::KeywordSetDecl& decl = pass.keywords.sets[s];
        std::string keyword = choices[s] && *choices[s] < decl.keywords.size()
                                  ? decl.keywords[*choices[s]]
                                  : std::string();
        origins.push_back({{"keyword", keyword.empty() ? "_" : keyword},
                           {"set", s},
                           {"directive", decl.directive},
                           {"shortcut", isShortcut(decl.directive)},
                           {"location", sourceMap.format(decl.location)}});
    }
    Json programs = Json::array();
    for (Stage stage : passStages(*request.compiled)) {
        uint32_t program = chosen.programs[stageIndex(stage)];
        size_t sharing = 0;
        for (const pack::PackVariant& other : request.compiled->variants)
            sharing += other.programs[stageIndex(stage)] == program ? 1 : 0;
        programs.push_back(
            {{"stage", stageName(stage)}, {"program", program}, {"shared_by", sharing}});
    }
    return {{"index", variant},
            {"keywords", keywordsOf(pass, chosen.key)},
            {"origins", std::move(origins)},
            {"programs", std::move(programs)},
            {"nearest", nearestJson(request, variant)}};
}

Json diffJson(const ExplainRequest& request, size_t a, size_t b) {
    const driver::CompiledPass& compiled = *request.compiled;
    Json stages = Json::array();
    for (Stage stage : passStages(compiled)) {
        uint32_t left = compiled.variantSources[a][stageIndex(stage)];
        uint32_t right = compiled.variantSources[b][stageIndex(stage)];
        Json lines = Json::array();
        if (left != right) {
            for (std::string& line :
                 lineDiff(request.build->prunedSources[left], request.build->prunedSources[right]))
                lines.push_back(std::move(line));
        }
        stages.push_back({{"stage", stageName(stage)},
                          {"same_source", left == right},
                          {"same_program", compiled.variants[a].programs[stageIndex(stage)] ==
                                               compiled.variants[b].programs[stageIndex(stage)]},
                          {"lines", std::move(lines)}});
    }
    auto side = [&](size_t v) {
        const variants::VariantKey& key = compiled.variants[v].key;
        return Json{{"index", v}, {"keywords", keywordsOf(*request.pass, key)}};
    };
    return {{"a", side(a)}, {"b", side(b)}, {"stages", std::move(stages)}};
}

}  // namespace

nlohmann::ordered_json explainJson(const ExplainRequest& request,
                                   const includes::SourceMap& sourceMap) {
    Json report;
    report["shader"] = request.shader->ast.name;
    report["pass"] = request.pass->index;
    report["light_mode"] = request.pass->pass->lightMode();
    report["variants"] = request.compiled->variants.size();
    report["sets"] = setsJson(request, sourceMap);
    report["stages"] = stagesJson(request);
    if (request.variant) report["variant"] = variantJson(request, *request.variant, sourceMap);
    if (request.diff) report["diff"] = diffJson(request, request.diff->first, request.diff->second);
    return report;
}

std::optional<size_t> findVariant(const frontend::LoadedPass& pass,
                                  const driver::CompiledPass& compiled,
                                  const std::vector<std::string>& keywords) {
    variants::VariantKey key = pass.space->table().keyOf(keywords);
    for (size_t v = 0; v < compiled.variants.size(); ++v) {
        if (compiled.variants[v].key == key) return v;
    }
    return std::nullopt;
}

}  // namespace varc::cli
