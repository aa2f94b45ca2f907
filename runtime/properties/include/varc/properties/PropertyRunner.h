// SPDX-License-Identifier: Apache-2.0
// PropertyRunner: draws a lighting shader's generated scenes (PropertyScenes) with a Renderer and
// checks the metamorphic relations between the renders (ImageRelations), each with the
// tolerance docs/PROPERTIES.md justifies; failing relations keep their worst pixels and images.
#pragma once

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "varc/reader/Pack.h"
#include "varc/reader/ShaderView.h"
#include "varc/render/Renderer.h"

namespace varc::properties {

struct PropertyOptions {
    std::string outDir = "validate-out";  // images of failing relations: <outDir>/<shader>/
    uint32_t size = 64;                   // every render is size x size pixels
};

enum class Verdict { Pass, Fail, NotApplicable };
const char* verdictName(Verdict verdict);  // "pass", "FAIL", "n/a"

struct RelationOutcome {
    std::string relation;  // one of relationNames()
    Verdict verdict = Verdict::NotApplicable;
    // Why it failed: per failing case its scenes, the variants drawn, the worst pixels and the
    // images written; for n/a the light types the shader does not take.
    std::string detail;
};

struct ShaderReport {
    std::string shader;
    std::vector<RelationOutcome> relations;  // in relationNames() order
    std::string lights;  // the light types drawn: "directional point spot directional-cookie"
    size_t renders = 0;
    std::set<std::string> variants;  // every variant drawn (VariantView::describe())
    size_t litVariants = 0;          // variants of the ForwardBase and ForwardAdd passes
    std::string error;               // a render that failed ("" when all drew)
    bool passed() const;             // no error and no relation failed
};

// The relations in the order they are checked and printed: finite, dark, lit, out_of_range,
// black_cookie, white_cookie, additivity, additivity_ldr, intensity, translation, rotation,
// scale.
const std::vector<std::string>& relationNames();

// The shaders of |packs| with a ForwardBase pass, in pack order; a name in two packs once (the
// renderer draws the first pack's).
std::vector<runtime::ShaderView> lightingShaders(const std::vector<const runtime::Pack*>& packs);

class PropertyRunner {
public:
    // |renderer| draws with the packs |shader|s come from; it must outlive the runner.
    PropertyRunner(runtime::Renderer& renderer, PropertyOptions options);

    // Draws |shader|'s scenes and checks every relation; writes the images of failing cases.
    ShaderReport check(const runtime::ShaderView& shader);

private:
    runtime::Renderer& mRenderer;
    PropertyOptions mOptions;
};

}  // namespace varc::properties
