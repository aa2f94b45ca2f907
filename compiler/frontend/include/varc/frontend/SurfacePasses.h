// SPDX-License-Identifier: Apache-2.0
// Turns the surface programs of a parsed shader into the passes Unity's code generator makes.
#pragma once

#include <functional>
#include <string>

#include "varc/core/Diagnostic.h"
#include "varc/shaderlab/ShaderAst.h"

namespace varc::frontend {

// The text a surface program is analysed in (its program with the include files spliced);
// nullopt after reporting why it cannot be had.
using SurfaceTextProvider = std::function<std::optional<std::string>(const shaderlab::Pass&)>;

// Replaces every surface placeholder (Pass::surface) of |shader|, in place and in order, by its
// generated passes: "FORWARD" ForwardBase; "FORWARD" ForwardAdd unless `noforwardadd`; and
// "ShadowCaster" with `addshadow` (docs/SURFACE_SHADERS.md). `exclude_path:forward` generates
// no forward pass. Render state: the SubShader's, plus the blending of `alpha`/`decal` options;
// ForwardAdd blends additively with ZWrite Off. |textOf| gives the text each placeholder is
// analysed in. Returns false after reporting an error (at the `#pragma surface`); the shader is
// then partly expanded and must not be compiled.
bool generateSurfacePasses(shaderlab::ShaderFile& shader, const SurfaceTextProvider& textOf,
                           DiagnosticSink& sink);

}  // namespace varc::frontend
