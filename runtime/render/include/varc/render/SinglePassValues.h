// SPDX-License-Identifier: Apache-2.0
// The uniform values of the single-pass forward path (SHADER_ABI.md §4.12, `varc/SinglePassLit`):
// the frame's light buffer and each draw's light count and index lists. Pure CPU.
#pragma once

#include <span>

#include "varc/render/ShaderValues.h"
#include "varc/scene/Scene.h"
#include "varc/scene/VisibleLights.h"

namespace varc::render {

// _LightBuffer: per slot of |visible|, _VisibleLightColors = (colour x intensity, 0),
// _VisibleLightDirectionsOrPositions = (-forward, 0) for directional lights, (position, 1)
// otherwise, _VisibleLightAttenuations = (1/max(range², 1e-5), 0, a, b) with the spot terms of
// the 46/64 inner-angle rule (directional (0, 0, 0, 1), point a = 0, b = 1), and
// _VisibleLightSpotDirections = (-forward, 0). Unused slots are zero; every array has 16 elements.
ShaderValues lightBufferValues(const scene::Scene& scene, const scene::VisibleLightSet& visible);

// The spot fade constants (a, b) of a spot light with full cone angle |spotAngleDegrees|:
// outer = angle/2, tan(inner) = 46/64 tan(outer), a = 1/max(cos(inner) - cos(outer), 0.001),
// b = -cos(outer) a. Example: 90° gives outer 45°, inner ≈ 35.7°, a ≈ 9.53, b ≈ -6.74.
glm::vec2 spotFadeConstants(float spotAngleDegrees);

// UnityPerDraw's light members for |list|: unity_LightIndicesOffsetAndCount = (0, count, 0, 0),
// unity_4LightIndices0/1 = slots 0-3 / 4-7 as floats (unused components 0).
ShaderValues drawLightValues(const scene::ObjectLightList& list);

}  // namespace varc::render
