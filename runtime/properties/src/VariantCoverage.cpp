// SPDX-License-Identifier: Apache-2.0
// The coverage renders and the `every_variant` relation of a property check.
#include <optional>
#include <set>
#include <vector>

#include "PropertySteps.h"
#include "varc/reader/PassView.h"
#include "varc/variants/LightKeywords.h"

namespace varc::properties {

namespace {

// Four point lights drawn per vertex in the base pass (VERTEXLIGHT_ON).
std::vector<scene::Light> vertexLights() {
    std::vector<scene::Light> lights;
    for (int i = 0; i < 4; ++i) {
        scene::Light light = keyPoint();
        light.renderMode = scene::LightRenderMode::NotImportant;
        light.transform.position.x += 0.5f * static_cast<float>(i);
        lights.push_back(light);
    }
    return lights;
}

// The variants of |shader|'s (first) ForwardBase and ForwardAdd passes that the forward renderer
// can select for some light (variants::lightKeywords: light type, cookie, shadows, vertex
// lights, HDR; light probes on; no material keywords), as VariantView::describe() gives them.
std::set<std::string> reachableVariants(const reader::ShaderView& shader) {
    std::set<std::string> reachable;
    for (const char* lightMode : {"ForwardBase", "ForwardAdd"}) {
        std::optional<reader::PassView> pass = shader.pass(std::string_view(lightMode));
        if (!pass) continue;
        for (auto type : {variants::LightType::Directional, variants::LightType::Point,
                          variants::LightType::Spot}) {
            for (bool cookie : {false, true}) {
                for (auto shadows : {variants::ShadowMode::None, variants::ShadowMode::Hard,
                                     variants::ShadowMode::Soft}) {
                    for (int vertexLightCount : {0, 4}) {
                        variants::LightDescription light;
                        light.type = type;
                        light.cookie = cookie;
                        light.shadows = shadows;
                        light.vertexLightCount = vertexLightCount;
                        light.lightProbes = true;
                        for (bool hdr : {false, true}) {
                            light.hdr = hdr;
                            auto variant = pass->lookup(light, variants::SelectionPolicy::Closest);
                            if (variant) reachable.insert(variant->describe());
                        }
                    }
                }
            }
        }
    }
    return reachable;
}

}  // namespace

std::string drawCoverage(ShaderCheck& c, const LightSupport& support,
                         const std::pair<std::string, std::string>& cookies,
                         const scene::Scene& empty) {
    auto lit = [&](const std::vector<scene::Light>& lights) { return withLights(empty, lights); };
    using scene::Light;
    std::string why;
    bool directionalShadows = true;
    Light main = keyDirectional();
    main.renderMode = scene::LightRenderMode::Important;
    for (scene::ShadowType shadows : {scene::ShadowType::Hard, scene::ShadowType::Soft}) {
        const std::string kind = shadows == scene::ShadowType::Hard ? "hard" : "soft";
        auto scene = [&](bool withDirectional) {
            std::vector<Light> lights{main};
            if (support.point) lights.push_back(keyPoint());
            if (support.spot) lights.push_back(keySpot());
            if (support.directionalCookie)
                lights.push_back(withCookie(secondDirectional(), cookies.first));
            if (support.pointCookie) lights.push_back(withCookie(keyPoint(), "white"));
            for (Light& light : lights)
                if (withDirectional || light.type != scene::LightType::Directional)
                    light.shadows = shadows;
            // Vertex lights with hard shadows only: the base pass's
            // SHADOWS_SCREEN is the same for soft shadows, so the soft
            // scene draws it without VERTEXLIGHT_ON.
            if (shadows == scene::ShadowType::Hard)
                for (const Light& light : vertexLights()) lights.push_back(light);
            return lit(lights);
        };
        const std::string label = "coverage " + kind + " shadows";
        if (directionalShadows && !c.tryRender(label, scene(true), why)) directionalShadows = false;
        if (!directionalShadows) c.render(label + " (no directional)", scene(false));
        if (!support.forwardAdd || !directionalShadows) continue;
        Light second = secondDirectional();
        second.shadows = shadows;
        c.render(label + ", second directional", lit({main, second}));
    }
    std::vector<Light> vertexLit{main};
    for (const Light& light : vertexLights()) vertexLit.push_back(light);
    c.render("coverage vertex lights", lit(vertexLit));
    return why;
}

void checkEveryVariant(ShaderCheck& c, const reader::ShaderView& shader, ShaderReport& report,
                       const std::string& why) {
    if (!report.error.empty()) return;
    const std::set<std::string> reachable = reachableVariants(shader);
    std::vector<std::string> missing;
    for (const std::string& variant : reachable) {
        if (report.variants.count(variant)) continue;
        if (!why.empty() && variant.find("SHADOWS_SCREEN") != std::string::npos) continue;
        missing.push_back(variant);
    }
    RelationOutcome& outcome = c.outcomeOf("every_variant");
    outcome.verdict = missing.empty() ? Verdict::Pass : Verdict::Fail;
    if (missing.empty()) return;
    outcome.detail = std::to_string(missing.size()) + " of " + std::to_string(reachable.size()) +
                     " variants a light selects were not drawn:";
    for (const std::string& variant : missing) outcome.detail += " [" + variant + "]";
    if (!why.empty()) outcome.detail += "; SHADOWS_SCREEN variants left out: " + why;
    outcome.detail += "\n";
}

}  // namespace varc::properties
