// SPDX-License-Identifier: Apache-2.0
// PropertyRunner: one lighting shader's renders and the relations between them; the tolerances
// are derived in docs/PROPERTIES.md.
#include "varc/properties/PropertyRunner.h"

#include <set>
#include <utility>

#include "PropertySteps.h"
#include "varc/properties/PropertyScenes.h"
#include "varc/reader/PassView.h"

namespace varc::properties {

const char* modelName(LightingModel model) {
    switch (model) {
        case LightingModel::Lit:
            return "lit";
        case LightingModel::NotLit:
            return "not-lit";
        case LightingModel::NonLinear:
            return "non-linear";
    }
    return "?";
}

const std::vector<std::string>& notLitRelations() {
    static const std::vector<std::string> kNames{"dark",           "lit",          "out_of_range",
                                                 "black_cookie",   "white_cookie", "additivity",
                                                 "additivity_ldr", "intensity"};
    return kNames;
}

const char* verdictName(Verdict verdict) {
    switch (verdict) {
        case Verdict::Pass:
            return "pass";
        case Verdict::Fail:
            return "FAIL";
        case Verdict::NotApplicable:
            return "n/a";
    }
    return "?";
}

bool ShaderReport::passed() const {
    if (!error.empty()) return false;
    for (const RelationOutcome& outcome : relations)
        if (outcome.verdict == Verdict::Fail) return false;
    return true;
}

size_t ShaderReport::litVariantsDrawn() const {
    size_t count = 0;
    for (const std::string& variant : variants)
        if (variant.find("(LightMode ForwardBase)") != std::string::npos ||
            variant.find("(LightMode ForwardAdd)") != std::string::npos)
            ++count;
    return count;
}

const std::vector<std::string>& relationNames() {
    static const std::vector<std::string> kNames{
        "finite",       "dark",         "lit",        "out_of_range",
        "black_cookie", "white_cookie", "additivity", "additivity_ldr",
        "intensity",    "translation",  "rotation",   "mirror",
        "scale",        "light_axis",   "behind",     "forward_deferred",
        "every_variant"};
    return kNames;
}

std::vector<reader::ShaderView> lightingShaders(const std::vector<const reader::Pack*>& packs) {
    std::vector<reader::ShaderView> shaders;
    std::set<std::string, std::less<>> seen;
    for (const reader::Pack* pack : packs) {
        for (size_t i = 0; i < pack->shaderCount(); ++i) {
            reader::ShaderView shader = pack->shader(i);
            if (!shader.pass("ForwardBase")) continue;
            if (seen.insert(std::string(shader.name())).second) shaders.push_back(shader);
        }
    }
    return shaders;
}

PropertyRunner::PropertyRunner(render::Renderer& renderer, PropertyOptions options)
    : mRenderer(renderer), mOptions(std::move(options)) {}

ShaderReport PropertyRunner::check(const reader::ShaderView& shader) {
    ShaderReport report;
    report.shader = std::string(shader.name());
    ShaderCheck check(mRenderer, mOptions, report);
    auto cookies = writeCookies(mOptions.outDir);
    if (!cookies) {
        report.error = cookies.error().detail;
        return report;
    }
    for (const char* lightMode : {"ForwardBase", "ForwardAdd"}) {
        if (std::optional<reader::PassView> pass = shader.pass(lightMode))
            report.litVariants += pass->variantCount();
    }
    const LightSupport support = lightSupportOf(shader);
    report.lights = "directional";
    if (support.point) report.lights += " point";
    if (support.spot) report.lights += " spot";
    if (support.directionalCookie) report.lights += " directional-cookie";
    if (support.pointCookie) report.lights += " point-cookie";
    const std::string noDirectionalShadows =
        checkRelations(check, report.shader, support, *cookies, mOptions.size);
    checkEveryVariant(check, shader, report, noDirectionalShadows);
    classify(check, support, lightInputsOf(litPassReflections(shader)), report);
    return report;
}

}  // namespace varc::properties