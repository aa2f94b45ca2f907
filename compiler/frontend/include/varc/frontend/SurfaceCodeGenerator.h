// SPDX-License-Identifier: Apache-2.0
// Writes the vertex and fragment programs of the passes a surface program becomes.
#pragma once

#include <string>

#include "varc/frontend/SurfaceAnalysis.h"
#include "varc/shaderlab/ShaderAst.h"

namespace varc::frontend {

enum class SurfacePassKind { ForwardBase, ForwardAdd, ShadowCaster };

// "ForwardBase", "ForwardAdd" or "ShadowCaster": the LightMode of a generated pass.
std::string surfacePassLightMode(SurfacePassKind kind);

// The code around the user's program for one generated pass (docs/SURFACE_SHADERS.md):
// |before|: the pass's UNITY_PASS_* define, the include files the lighting needs, INTERNAL_DATA
// and WorldNormalVector/WorldReflectionVector, `#pragma vertex/fragment` and the pass's
// multi_compile shortcuts; |after|: the interpolators, a vertex program that applies the
// vertex modifier and fills them, and a fragment program that fills Input, calls the surface
// function, lights the result with Lighting<MODEL> and applies finalcolor, fog and alpha.
// |location| is the `#pragma surface`.
shaderlab::GeneratedCode generateSurfaceCode(const shaderlab::SurfaceProgram& program,
                                             const SurfaceFacts& facts, SurfacePassKind kind);

// The blend mode alpha:blend / plain `alpha` resolves to for |program|: premultiplied for the
// physically based models (Standard, StandardSpecular), fade for the others, as Unity does.
shaderlab::SurfaceOptions::Alpha effectiveAlpha(const shaderlab::SurfaceProgram& program);

}  // namespace varc::frontend
