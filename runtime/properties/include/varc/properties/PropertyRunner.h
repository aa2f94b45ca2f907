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

// One failing case of a relation, for the HTML report: what detail says about it, in fields.
struct FailedCase {
    std::string label;                  // the case ("point-far", ...)
    std::string finding;                // the worst pixels, or what the case found
    std::vector<std::string> variants;  // the distinct variants its render drew, in draw order
    // The PNGs written (<outDir>/<shader>/<relation>.<label>.*.png): actual, then expected and
    // diff when the relation compares with an expected image; empty when they were not written.
    std::vector<std::string> images;
};

struct RelationOutcome {
    std::string relation;  // one of relationNames()
    Verdict verdict = Verdict::NotApplicable;
    // Why it failed: per failing case its scenes, the variants drawn, the worst pixels and the
    // images written; for n/a by classification the model's reason ("" when the shader does not
    // take the light types the relation needs).
    std::string detail;
    std::vector<FailedCase> cases;  // the failing cases that drew (and wrote images), in order
};

// What the renders show about a shader's lighting (docs/PROPERTIES.md, "Classification").
enum class LightingModel {
    Lit,        // the key lights change the image: every relation applies
    NotLit,     // no program of the lit passes reads a light input (LightInputs.h) and no key
                // light changes 2% of the pixels: unlit, emissive, a debug view; the relations
                // about lights (notLitRelations()) are n/a. Reading a light input makes a
                // shader Lit, and `lit` FAILs when it then does not respond.
    NonLinear,  // lit, but a doubled intensity brightens without doubling the light's
                // contribution (toon ramps, clamped colours): `intensity` is n/a
};
const char* modelName(LightingModel model);  // "lit", "not-lit", "non-linear"

// The relations that are n/a for a shader that is not lit: dark, lit, out_of_range,
// black_cookie, white_cookie, additivity, additivity_ldr, intensity.
const std::vector<std::string>& notLitRelations();

struct ShaderReport {
    std::string shader;
    std::vector<RelationOutcome> relations;  // in relationNames() order
    LightingModel model = LightingModel::Lit;
    std::string modelReason;  // the measurement that decided a model other than Lit
    std::string lights;  // the light types drawn: "directional point spot directional-cookie"
    size_t renders = 0;
    std::set<std::string> variants;  // every variant drawn (VariantView::describe())
    size_t litVariants = 0;          // variants of the ForwardBase and ForwardAdd passes
    std::string error;               // a render that failed ("" when all drew)
    // No error and no relation failed. The findings of the reflection (a lit shader that does
    // not respond, a response without a light input, a ForwardAdd pass that reads none) are
    // FAILs of `lit`, so they fail this too.
    bool passed() const;
    size_t litVariantsDrawn() const;  // the |variants| of ForwardBase and ForwardAdd passes
};

// The relations in the order they are checked and printed: finite, dark, lit, out_of_range,
// black_cookie, white_cookie, additivity, additivity_ldr, intensity, translation, rotation,
// mirror, scale, light_axis, behind, forward_deferred, every_variant.
const std::vector<std::string>& relationNames();

// The shaders of |packs| with a ForwardBase pass, in pack order; a name in two packs once (the
// renderer draws the first pack's).
std::vector<reader::ShaderView> lightingShaders(const std::vector<const reader::Pack*>& packs);

class PropertyRunner {
public:
    // |renderer| draws with the packs |shader|s come from; it must outlive the runner.
    PropertyRunner(render::Renderer& renderer, PropertyOptions options);

    // Draws |shader|'s scenes and checks every relation; writes the images of failing cases.
    ShaderReport check(const reader::ShaderView& shader);

private:
    render::Renderer& mRenderer;
    PropertyOptions mOptions;
};

}  // namespace varc::properties
