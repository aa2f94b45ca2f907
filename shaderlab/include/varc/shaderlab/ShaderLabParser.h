// SPDX-License-Identifier: Apache-2.0
// Parses ShaderLab text (.shader files) into a ShaderFile.
#pragma once

#include <optional>
#include <string_view>

#include "varc/core/Diagnostic.h"
#include "varc/shaderlab/ShaderAst.h"

namespace varc::shaderlab {

// Parses one .shader file whose text is registered as |file|. Keywords are case-insensitive
// as in Unity. Program blocks are captured verbatim (not parsed). Every error carries
// path:line:col through |file|. Returns nullopt after reporting at least one error.
//
// Example:
//   Shader "A" { SubShader { Pass { Tags { "LightMode"="ForwardAdd" } Blend One One
//                                   CGPROGRAM ... ENDCG } } }
//   -> one SubShader with one Pass, lightMode() == "ForwardAdd", state.blend = {One, One}.
std::optional<ShaderFile> parseShaderLab(std::string_view text, FileId file, DiagnosticSink& sink);

}  // namespace varc::shaderlab
