// SPDX-License-Identifier: Apache-2.0
// Decides whether a shader is lit, not lit or non-linear, and marks what then does not apply.
#include <string>
#include <vector>

#include "PropertySteps.h"
#include "PropertyTolerances.h"
#include "varc/properties/ImageRelations.h"
#include "varc/properties/LightInputs.h"

namespace varc::properties {

namespace {

using image::Image;

bool atLeastShare(size_t pixels, const Image& image) {
    return pixels * 100 >= kSharePercent * image.width() * image.height();
}

void markNotApplicable(ShaderCheck& c, const std::vector<std::string>& relations,
                       const std::string& reason) {
    for (const std::string& relation : relations) {
        RelationOutcome& outcome = c.outcomeOf(relation);
        outcome.verdict = Verdict::NotApplicable;
        outcome.detail = reason;
        outcome.cases.clear();  // images already written stay on disk, not in the report
    }
}

// True when no key light the shader takes changes kSharePercent of the pixels by more than
// kVisible against the unlit render; |counts| gets the counts ("directional 0, point 3 of 4096").
// False, with |counts| empty, when a frame is missing.
bool noKeyLightResponse(const ShaderCheck& c, const LightSupport& support, std::string& counts) {
    const render::RenderedFrame* none = c.frame("no lights");
    if (!none) return false;
    std::vector<std::string> keys{"directional"};
    if (support.point) keys.push_back("point");
    if (support.spot) keys.push_back("spot");
    bool responds = false;
    for (const std::string& key : keys) {
        const render::RenderedFrame* lit = c.frame(key);
        if (!lit) {
            counts.clear();
            return false;
        }
        const size_t changed = pixelsChanged(lit->image, none->image, kVisible);
        responds = responds || atLeastShare(changed, lit->image);
        counts += (counts.empty() ? "" : ", ") + key + " " + std::to_string(changed);
    }
    counts += " of " + std::to_string(size_t{none->image.width()} * none->image.height());
    return !responds;
}

// The first 8 of |names| and how many more: "_LightColor0 ... unity_SHAr and 26 more".
std::string joined(const std::vector<std::string>& names) {
    constexpr size_t kShown = 8;
    std::string text;
    for (size_t i = 0; i < names.size() && i < kShown; ++i)
        text += (text.empty() ? "" : " ") + names[i];
    if (names.size() > kShown) text += " and " + std::to_string(names.size() - kShown) + " more";
    return text;
}

// "non-linear" when `intensity` failed but every doubled light brightens (no pixel darker than
// with the light once, within half-float rounding) and one of them brightens kSharePercent of the
// pixels by more than kVisible: the shader responds to intensity, only not in proportion.
bool nonLinear(const ShaderCheck& c, const LightSupport& support, std::string& counts) {
    std::vector<std::pair<std::string, std::string>> cases{{"directional", "directional x2"}};
    if (support.point) cases.emplace_back("point", "point x2");
    bool responds = false;
    for (const auto& [once, twice] : cases) {
        const render::RenderedFrame* a = c.frame(once);
        const render::RenderedFrame* b = c.frame(twice);
        if (!a || !b) return false;
        const Growth growth = contributionGrowth(a->image, b->image, kZero, 2 * kHalfUlp, kVisible);
        if (growth.shrinking > 0) return false;
        responds = responds || atLeastShare(growth.growing, a->image);
        counts +=
            (counts.empty() ? "" : ", ") + once + " x2 brightens " + std::to_string(growth.growing);
    }
    return responds;
}

}  // namespace

// Decides the report's LightingModel from the reflection and the renders and marks the relations
// that do not apply; `lit` fails where the two disagree (decideLightModel()).
void classify(ShaderCheck& c, const LightSupport& support, const LightInputReport& inputs,
              ShaderReport& report) {
    if (!report.error.empty()) return;
    std::string counts;
    const bool unresponsive = noKeyLightResponse(c, support, counts);
    const bool measured = !counts.empty();
    const LightModelDecision decision = decideLightModel(inputs, measured && !unresponsive);
    if (decision.notLit && measured) {
        report.model = LightingModel::NotLit;
        report.modelReason =
            "not a lit shader: its ForwardBase and ForwardAdd programs read no light input, and "
            "no key light changes 2% of the pixels by > 1/64 (" +
            counts + ")";
        markNotApplicable(c, notLitRelations(), report.modelReason);
    }
    if (inputs.lit() && unresponsive) {
        // requireLight() has failed `lit` on the images; say why that is not excused.
        const std::string why = "the programs read the light inputs " + joined(inputs.read) +
                                ", yet no key light changes the image (" + counts + ")";
        if (c.outcomeOf("lit").verdict == Verdict::Fail)
            c.outcomeOf("lit").detail += why + "\n";
        else
            c.failWithoutRender("lit", "reflection", why);
    }
    for (const std::string& failure : decision.litFailures)
        c.failWithoutRender("lit", "reflection", failure);
    if (report.model == LightingModel::NotLit) return;
    counts.clear();
    if (c.outcomeOf("intensity").verdict == Verdict::Fail && nonLinear(c, support, counts)) {
        report.model = LightingModel::NonLinear;
        report.modelReason =
            "non-linear model: a doubled light brightens, darkens nothing, but does not double "
            "its contribution (" +
            counts + " pixels): intensity is n/a";
        markNotApplicable(c, {"intensity"}, report.modelReason);
    }
}

}  // namespace varc::properties
