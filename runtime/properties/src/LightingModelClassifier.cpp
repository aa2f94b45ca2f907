// SPDX-License-Identifier: Apache-2.0
// Decides whether a shader is lit, not lit or non-linear, and marks what then does not apply.
#include <string>
#include <vector>

#include "PropertySteps.h"
#include "PropertyTolerances.h"
#include "varc/properties/ImageRelations.h"

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

// "not-lit" when no key light the shader takes changes kSharePercent of the pixels by more than
// kVisible against the unlit render; returns the counts ("directional 0, point 3 of 4096").
bool notLit(const ShaderCheck& c, const LightSupport& support, std::string& counts) {
    const render::RenderedFrame* none = c.frame("no lights");
    if (!none) return false;
    std::vector<std::string> keys{"directional"};
    if (support.point) keys.push_back("point");
    if (support.spot) keys.push_back("spot");
    for (const std::string& key : keys) {
        const render::RenderedFrame* lit = c.frame(key);
        if (!lit) return false;
        const size_t changed = pixelsChanged(lit->image, none->image, kVisible);
        if (atLeastShare(changed, lit->image)) return false;
        counts += (counts.empty() ? "" : ", ") + key + " " + std::to_string(changed);
    }
    counts += " of " + std::to_string(size_t{none->image.width()} * none->image.height());
    return true;
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

// Decides the report's LightingModel from the renders and marks the relations that do not apply.
void classify(ShaderCheck& c, const LightSupport& support, ShaderReport& report) {
    if (!report.error.empty()) return;
    std::string counts;
    if (notLit(c, support, counts)) {
        report.model = LightingModel::NotLit;
        report.modelReason =
            "not a lit shader: no key light changes 2% of the pixels by > 1/64 (" + counts + ")";
        markNotApplicable(c, notLitRelations(), report.modelReason);
        return;
    }
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
