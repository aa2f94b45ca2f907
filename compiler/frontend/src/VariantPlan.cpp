// SPDX-License-Identifier: Apache-2.0
// planPass: materials and collections, then settings stripping, then the user's strip rules.
#include "varc/frontend/VariantPlan.h"

#include <optional>
#include <utility>

#include "varc/core/AsciiCase.h"
#include "varc/frontend/ShaderLoader.h"

namespace varc::frontend {

namespace {

// Compiles the rules of |rules| that apply to |pass| (the others never match) and applies them.
std::vector<variants::PassStripRule> compileRules(const LoadedShader& shader,
                                                  const LoadedPass& pass,
                                                  const std::vector<variants::StripRule>& rules) {
    std::vector<variants::PassStripRule> compiled;
    compiled.reserve(rules.size());
    for (const variants::StripRule& rule : rules) {
        if (variants::stripRuleApplies(rule, shader.ast.name, pass.pass->name,
                                       pass.pass->lightMode())) {
            compiled.push_back(variants::compileStripRule(rule, pass.keywords,
                                                          pass.space->table()));
        } else {
            variants::PassStripRule never;
            never.never = true;
            compiled.push_back(never);
        }
    }
    return compiled;
}

std::vector<std::string> namesOf(const std::vector<variants::StripRule>& rules) {
    std::vector<std::string> names;
    for (const variants::StripRule& rule : rules) names.push_back(rule.name);
    return names;
}

// The first of |rules| that removes |key|, or nullopt.
std::optional<size_t> firstMatch(const std::vector<variants::PassStripRule>& rules,
                                 const variants::VariantKey& key) {
    for (size_t r = 0; r < rules.size(); ++r) {
        std::vector<variants::VariantKey> one = {key};
        if (variants::applyStripRules({rules[r]}, one)[0] > 0) return r;
    }
    return std::nullopt;
}

// The material requests, then the collection entries for this pass's PassType.
std::vector<variants::KeywordRequest> requestsFor(const LoadedPass& pass,
                                                  const ShaderDemand& demand) {
    std::vector<variants::KeywordRequest> requests = demand.requests;
    int passType = passTypeOfLightMode(pass.pass->lightMode());
    for (const ShaderDemand::CollectionRequest& entry : demand.collectionRequests) {
        if (entry.passType == passType) requests.push_back(entry.request);
    }
    return requests;
}

}  // namespace

int passTypeOfLightMode(std::string_view lightMode) {
    static constexpr std::pair<std::string_view, int> kPassTypes[] = {
        {"", 0},          {"always", 0},       {"vertex", 1},        {"vertexlm", 2},
        {"forwardbase", 4}, {"forwardadd", 5}, {"prepassbase", 6},   {"prepassfinal", 7},
        {"shadowcaster", 8}, {"deferred", 10}, {"meta", 11},         {"motionvectors", 12}};
    std::string lower = toAsciiLower(lightMode);
    for (const auto& [name, type] : kPassTypes) {
        if (lower == name) return type;
    }
    return 13;
}

VariantPlan planPass(const LoadedShader& shader, const LoadedPass& pass,
                     const ShaderDemand& demand, const std::vector<variants::StripRule>& rules,
                     uint64_t limit) {
    VariantPlan plan;
    auto selection = std::make_shared<variants::MaterialSelection>(
        variants::MaterialSelection::select(pass.keywords, *pass.space, requestsFor(pass, demand),
                                            demand.alwaysIncluded));
    plan.counts.declared = selection->counts().declared;
    plan.counts.materials = selection->count();
    plan.counts.settings = plan.counts.rules = plan.counts.materials;
    plan.settingsRemoved.assign(demand.settingsRules.size(), 0);
    plan.rulesRemoved.assign(rules.size(), 0);
    plan.settingsRules = compileRules(shader, pass, demand.settingsRules);
    plan.userRules = compileRules(shader, pass, rules);
    plan.settingsRuleNames = namesOf(demand.settingsRules);
    plan.userRuleNames = namesOf(rules);
    if (plan.counts.materials <= limit) {
        plan.enumerated = true;
        plan.keys = selection->enumerate();
        plan.settingsRemoved = variants::applyStripRules(plan.settingsRules, plan.keys);
        plan.counts.settings = plan.keys.size();
        plan.rulesRemoved = variants::applyStripRules(plan.userRules, plan.keys);
        plan.counts.rules = plan.keys.size();
    }
    plan.selection = std::move(selection);
    return plan;
}

std::string explainVariant(const VariantPlan& plan, const variants::VariantKey& key, bool& ships) {
    ships = false;
    variants::VariantVerdict verdict = plan.selection->explain(key);
    if (!verdict.ships) return "left out: " + verdict.text;
    if (auto rule = firstMatch(plan.settingsRules, key)) {
        return "removed by Graphics Settings (" + plan.settingsRuleNames[*rule] + ")";
    }
    if (auto rule = firstMatch(plan.userRules, key)) {
        return "removed by strip rule '" + plan.userRuleNames[*rule] + "'";
    }
    ships = true;
    return "ships: " + verdict.text;
}

}  // namespace varc::frontend
