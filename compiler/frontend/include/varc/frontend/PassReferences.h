// SPDX-License-Identifier: Apache-2.0
// Passes a shader borrows from other shaders: `UsePass` entries and the shadow caster a shader
// without one inherits through its `Fallback` chain, resolved the way Unity resolves them.
#pragma once

#include "varc/core/Diagnostic.h"
#include "varc/frontend/ShaderCatalog.h"
#include "varc/shaderlab/ShaderAst.h"

namespace varc::frontend {

// Resolves the references of |shader| in place, finding other shaders through |catalog|:
//  * `UsePass "Some/Shader/PASSNAME"` becomes a copy of the pass named PASSNAME (compared
//    without case: Unity upper-cases pass names) of the first subshader of "Some/Shader" that
//    has one, with its own tags, render state and program. A pass that cannot be found is a
//    warning, and the entry stays a reference that compiles nothing (Unity skips it too).
//  * A shader with no `ShadowCaster` pass in any subshader gets the ShadowCaster passes of its
//    fallback, or of the fallback's fallback, and so on (the first shader of the chain that has
//    one), appended to its last subshader: Unity renders the shadows of such a shader with its
//    fallback's caster. An unknown fallback is a warning (the shader casts no shadows).
// Copied passes record where they came from (Pass::origin). Reference chains are followed to a
// depth of 16; a cycle is a warning and is not followed. Nothing here is an error: Unity builds
// such shaders too, without the pass.
void resolvePassReferences(shaderlab::ShaderFile& shader, ShaderCatalog& catalog,
                           DiagnosticSink& sink);

}  // namespace varc::frontend
