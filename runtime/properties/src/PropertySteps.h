// SPDX-License-Identifier: Apache-2.0
// The steps of PropertyRunner::check: cookies, the relations, the coverage renders, the model.
#pragma once

#include <cstdint>
#include <string>
#include <utility>

#include "ShaderCheck.h"
#include "varc/core/Result.h"
#include "varc/properties/LightInputs.h"
#include "varc/properties/PropertyRunner.h"
#include "varc/properties/PropertyScenes.h"
#include "varc/reader/ShaderView.h"
#include "varc/scene/Scene.h"

namespace varc::properties {

// Cookie PNGs in <outDir>/cookies: alpha 1 everywhere (white) and alpha 0 (black).
Result<std::pair<std::string, std::string>> writeCookies(const std::string& outDir);

// |light| with the cookie texture |cookie| (a path, or a built-in name such as "white").
scene::Light withCookie(scene::Light light, const std::string& cookie);

// The relations on HDR renders (and additivity_ldr on RGBA8), in relationNames() order, then
// the coverage renders; returns why directional shadows were not drawn ("" when they were).
std::string checkRelations(ShaderCheck& c, const std::string& shader, const LightSupport& support,
                           const std::pair<std::string, std::string>& cookies, uint32_t size);

// The renders that reach the variants the relations leave out (each is checked for `finite`):
// per shadow type (hard, soft) the main light and every light type the shader takes, with
// cookies, in one scene (vertex lights too with hard shadows), and the second directional light
// shadowed under an unshadowed main light (both Important: the main light is the first
// directional light by importance, then brightness); vertex lights alone. When directional
// shadows cannot be drawn (no screen-space shadow shader in the packs) the scenes are drawn
// without them; returns why ("" when every coverage scene drew).
// |empty| is the scene the lights are added to.
std::string drawCoverage(ShaderCheck& c, const LightSupport& support,
                         const std::pair<std::string, std::string>& cookies,
                         const scene::Scene& empty);

// `every_variant`: each variant the renderer can select was drawn by some render of the check;
// when directional shadows could not be drawn (|why|), the SHADOWS_SCREEN variants are left out.
void checkEveryVariant(ShaderCheck& c, const reader::ShaderView& shader, ShaderReport& report,
                       const std::string& why);

// Decides the report's LightingModel from |inputs| (the light inputs the pack's reflection says
// the lit passes read) and the renders, marks the relations that do not apply, and fails `lit`
// for what the two disagree on (decideLightModel()).
void classify(ShaderCheck& c, const LightSupport& support, const LightInputReport& inputs,
              ShaderReport& report);

}  // namespace varc::properties
