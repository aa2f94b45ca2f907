// SPDX-License-Identifier: Apache-2.0
// SinglePassReference: renders a single-pass forward Scene (`"path": "single_pass"`, shader
// `varc/SinglePassLit`, or seed 003's `My Pipeline/Lit` with "reference": "seed003") on the CPU
// as the GPU should (docs/LIGHTING.md §8.4, §9.3): the light rules of
// varc::scene::VisibleLights, the lighting evaluated from the scene's lights (not from the GPU's
// light buffer), per-vertex lights at the vertices and interpolated. No Vulkan.
#pragma once

#include <functional>

#include "varc/core/Result.h"
#include "varc/reference/ReferenceRenderer.h"
#include "varc/scene/Scene.h"
#include "varc/scene/VisibleLights.h"

namespace varc::reference {

struct SinglePassReferenceOptions {
    // The ratio tan(inner)/tan(outer) of spot lights (seed 003's rule: 46/64).
    float spotInnerTangentRatio = 46.0f / 64.0f;
    // Mutation hook for tests: edits each object's light list after objectLightList.
    std::function<void(scene::ObjectLightList&)> editLights;
};

// The irradiance E_j of LIGHTING.md §8.4 that |light| gives a surface at |p| with unit normal
// |n| (seed 003's vertex stage passes an unnormalised one, as its shader does), in the shader's
// order of operations (float32).
glm::vec3 singlePassIrradiance(const scene::Light& light, const glm::vec3& p, const glm::vec3& n,
                               float spotInnerTangentRatio = 46.0f / 64.0f);

// Renders |scene| (camera.path must be SinglePass; every object's reference model
// "varc-single-pass-lit" (varc/SinglePassLit) or "seed003" (normals by M's 3x3 part, see the
// .cpp), albedo _Color, default (1, 1, 1, 1)). One opaque pass per object, quantised like the
// forward reference (LDR: RGBA8_UNORM rounding; HDR: half precision), alpha 1. Errors:
// Unsupported for another path, NotFound for another model, InvalidInput when _Color is not a
// colour (the message names the object).
Result<ReferenceImage> renderSinglePassReference(const scene::Scene& scene,
                                                 const SinglePassReferenceOptions& options = {});

}  // namespace varc::reference
