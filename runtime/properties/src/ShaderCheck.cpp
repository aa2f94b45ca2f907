// SPDX-License-Identifier: Apache-2.0
// ShaderCheck: draws each case once, checks every render is finite and records failures with
// images.
#include "ShaderCheck.h"

#include <cctype>
#include <filesystem>
#include <set>

#include "varc/image/Png.h"

namespace varc::properties {

namespace {

using image::Image;

std::string fileSafe(std::string text) {
    for (char& c : text)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_')) c = '_';
    return text;
}

// " [variant] [variant]": the distinct variants |frame| drew, in first-draw order.
std::string variantList(const render::RenderedFrame& frame) {
    std::set<std::string> seen;
    std::string list;
    for (const std::string& variant : frame.variants)
        if (seen.insert(variant).second) list += " [" + variant + "]";
    return list;
}

}  // namespace

ShaderCheck::ShaderCheck(render::Renderer& renderer, const PropertyOptions& options,
                         ShaderReport& report)
    : mRenderer(renderer), mOptions(options), mReport(report) {
    for (const std::string& name : relationNames())
        mReport.relations.push_back({name, Verdict::NotApplicable, {}, {}});
}

const render::RenderedFrame* ShaderCheck::render(const std::string& label,
                                                 const scene::Scene& scene) {
    auto found = mFrames.find(label);
    if (found != mFrames.end()) return &found->second;
    auto frame = mRenderer.render(scene);
    if (!frame) {
        if (mReport.error.empty()) mReport.error = label + ": " + frame.error().detail;
        return nullptr;
    }
    ++mReport.renders;
    mReport.variants.insert(frame->variants.begin(), frame->variants.end());
    checkFinite(label, *frame);
    return &mFrames.emplace(label, std::move(*frame)).first->second;
}

void ShaderCheck::relate(const std::string& relation, const std::string& label,
                         const render::RenderedFrame* actual,
                         const std::vector<std::pair<const render::RenderedFrame*, float>>& terms,
                         const Tolerance& tolerance) {
    if (!actual) return;
    std::vector<Term> imageTerms;
    for (const auto& [frame, weight] : terms) {
        if (!frame) return;
        imageTerms.push_back({&frame->image, weight});
    }
    RelationCheck check = checkRelation(actual->image, imageTerms, tolerance);
    RelationOutcome& outcome = outcomeOf(relation);
    if (check.passed) {
        if (outcome.verdict == Verdict::NotApplicable) outcome.verdict = Verdict::Pass;
        return;
    }
    recordFailure(outcome, label, check.summary(), *actual, &check);
}

void ShaderCheck::requireLight(const std::string& label, const render::RenderedFrame* lit,
                               const render::RenderedFrame* unlit) {
    if (!lit || !unlit) return;
    const size_t pixels = size_t{lit->image.width()} * lit->image.height();
    const size_t brighter = pixelsBrighter(lit->image, unlit->image, 1.0f / 64.0f);
    RelationOutcome& outcome = outcomeOf("lit");
    if (brighter * 50 >= pixels) {
        if (outcome.verdict == Verdict::NotApplicable) outcome.verdict = Verdict::Pass;
        return;
    }
    recordFailure(outcome, label,
                  "only " + std::to_string(brighter) + " of " + std::to_string(pixels) +
                      " pixels brighter than with no lights (2% needed)",
                  *lit, nullptr);
}

void ShaderCheck::failWithoutRender(const std::string& relation, const std::string& label,
                                    const std::string& finding) {
    RelationOutcome& outcome = outcomeOf(relation);
    if (outcome.verdict != Verdict::Fail) outcome.detail.clear();  // an n/a reason no longer holds
    outcome.verdict = Verdict::Fail;
    outcome.detail += label + ": " + finding + "\n";
    outcome.cases.push_back(FailedCase{label, finding, {}, {}});
}

const render::RenderedFrame* ShaderCheck::tryRender(const std::string& label,
                                                    const scene::Scene& scene, std::string& why) {
    auto frame = mRenderer.render(scene);
    if (!frame) {
        why = label + ": " + frame.error().detail;
        return nullptr;
    }
    ++mReport.renders;
    mReport.variants.insert(frame->variants.begin(), frame->variants.end());
    checkFinite(label, *frame);
    return &mFrames.insert_or_assign(label, std::move(*frame)).first->second;
}

const render::RenderedFrame* ShaderCheck::flipped(const std::string& label,
                                                  const render::RenderedFrame* source) {
    if (!source) return nullptr;
    render::RenderedFrame frame = *source;
    frame.image = flippedLeftRight(source->image);
    return &mFrames.insert_or_assign(label, std::move(frame)).first->second;
}

const render::RenderedFrame* ShaderCheck::quarterTurned(const std::string& label,
                                                        const render::RenderedFrame* source) {
    if (!source) return nullptr;
    render::RenderedFrame frame = *source;
    frame.image = properties::quarterTurned(source->image);
    return &mFrames.insert_or_assign(label, std::move(frame)).first->second;
}

const render::RenderedFrame* ShaderCheck::frame(const std::string& label) const {
    auto found = mFrames.find(label);
    return found == mFrames.end() ? nullptr : &found->second;
}

RelationOutcome& ShaderCheck::outcomeOf(const std::string& relation) {
    for (RelationOutcome& outcome : mReport.relations)
        if (outcome.relation == relation) return outcome;
    return mReport.relations.front();
}

void ShaderCheck::checkFinite(const std::string& label, const render::RenderedFrame& frame) {
    RelationOutcome& outcome = outcomeOf("finite");
    NonFinite found = findNonFinite(frame.image);
    if (found.count == 0) {
        if (outcome.verdict == Verdict::NotApplicable) outcome.verdict = Verdict::Pass;
        return;
    }
    recordFailure(outcome, label,
                  std::to_string(found.count) + " pixels hold NaN or Inf, first (" +
                      std::to_string(found.firstX) + "," + std::to_string(found.firstY) + ")",
                  frame, nullptr);
}

void ShaderCheck::recordFailure(RelationOutcome& outcome, const std::string& label,
                                const std::string& finding, const render::RenderedFrame& frame,
                                const RelationCheck* check) {
    outcome.verdict = Verdict::Fail;
    FailedCase failed{label, finding, {}, {}};
    std::set<std::string> seen;
    for (const std::string& variant : frame.variants)
        if (seen.insert(variant).second) failed.variants.push_back(variant);
    outcome.detail += label + ": " + finding + "; variants:" + variantList(frame) +
                      writeImages(outcome.relation, label, frame.image, check, failed.images) +
                      "\n";
    outcome.cases.push_back(std::move(failed));
}

std::string ShaderCheck::writeImages(const std::string& relation, const std::string& label,
                                     const Image& actual, const RelationCheck* check,
                                     std::vector<std::string>& written) {
    std::filesystem::path dir = std::filesystem::path(mOptions.outDir) / fileSafe(mReport.shader);
    std::error_code error;
    std::filesystem::create_directories(dir, error);
    if (error) return " (images not written: " + error.message() + ")";
    std::string base = (dir / (relation + "." + fileSafe(label))).string();
    auto shown = [](const Image& image) {
        return image.isFloat() ? image.toRgba8(image::Tonemap::Reinhard) : image;
    };
    std::vector<std::pair<std::string, Image>> images{{base + ".actual.png", shown(actual)}};
    if (check) {
        images.emplace_back(base + ".expected.png", shown(check->expected));
        images.emplace_back(base + ".diff.png", check->diff);
    }
    for (const auto& [path, image] : images) {
        if (Status status = image::writePng(path, image); !status)
            return " (images not written: " + status.error().detail + ")";
    }
    for (const auto& image : images) written.push_back(image.first);
    return " -> " + base + ".*.png";
}

}  // namespace varc::properties
