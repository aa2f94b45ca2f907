// SPDX-License-Identifier: Apache-2.0
// ShaderCheck: the renders of one lighting shader, by case label, and the relations checked on
// them.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "varc/properties/ImageRelations.h"
#include "varc/properties/PropertyRunner.h"
#include "varc/render/Renderer.h"
#include "varc/scene/Scene.h"

namespace varc::properties {

// The renders of one shader, by case label, and the relations checked on them.
class ShaderCheck {
public:
    ShaderCheck(render::Renderer& renderer, const PropertyOptions& options, ShaderReport& report);

    // The frame of |scene| under |label| (drawn once); nullptr after recording a render error.
    const render::RenderedFrame* render(const std::string& label, const scene::Scene& scene);

    // Checks |relation| on case |label|: the render |actual| against sum(weight x render).
    void relate(const std::string& relation, const std::string& label,
                const render::RenderedFrame* actual,
                const std::vector<std::pair<const render::RenderedFrame*, float>>& terms,
                const Tolerance& tolerance);

    // Checks that |lit| is brighter than |unlit| by more than 1/64 on at least 2% of its pixels:
    // a key light in range lights the objects (so the other relations compare lit images).
    void requireLight(const std::string& label, const render::RenderedFrame* lit,
                      const render::RenderedFrame* unlit);

    // Fails |relation| on case |label| with |finding| and no render (a finding of the pack's
    // reflection, not of an image): its detail line and a FailedCase without variants or images.
    void failWithoutRender(const std::string& relation, const std::string& label,
                           const std::string& finding);

    // Like render(), for a coverage render that may fail without failing the check (directional
    // shadows need Hidden/varc/ScreenSpaceShadows in a pack): the error goes to |why|.
    const render::RenderedFrame* tryRender(const std::string& label, const scene::Scene& scene,
                                           std::string& why);

    // |source| with its image flipped left to right, kept under |label| (not a render).
    const render::RenderedFrame* flipped(const std::string& label,
                                         const render::RenderedFrame* source);

    // |source| with its image turned a quarter turn clockwise, kept under |label| (not a render).
    const render::RenderedFrame* quarterTurned(const std::string& label,
                                               const render::RenderedFrame* source);

    // The frame drawn under |label|, or nullptr (not drawn, or its render failed).
    const render::RenderedFrame* frame(const std::string& label) const;

    RelationOutcome& outcomeOf(const std::string& relation);

private:
    void checkFinite(const std::string& label, const render::RenderedFrame& frame);

    // Fails |outcome| on case |label|: its detail line (the finding, the variants |frame| drew,
    // the images written) and its FailedCase.
    void recordFailure(RelationOutcome& outcome, const std::string& label,
                       const std::string& finding, const render::RenderedFrame& frame,
                       const RelationCheck* check);

    // Writes <outDir>/<shader>/<relation>.<label>.{actual,expected,diff}.png, their paths to
    // |written| once all are written; " -> <files>" or " (images not written: why)".
    std::string writeImages(const std::string& relation, const std::string& label,
                            const image::Image& actual, const RelationCheck* check,
                            std::vector<std::string>& written);

    render::Renderer& mRenderer;
    const PropertyOptions& mOptions;
    ShaderReport& mReport;
    std::map<std::string, render::RenderedFrame> mFrames;
};

}  // namespace varc::properties
