// SPDX-License-Identifier: Apache-2.0
// Parses ShaderLab text (.shader files) into a ShaderFile.
#pragma once

#include <optional>
#include <string_view>

#include "varc/core/Diagnostic.h"
#include "varc/shaderlab/ShaderAst.h"

namespace varc::shaderlab {

// Parses one .shader file whose text is registered as |file|. Keywords are case-insensitive
// as in Unity. Program blocks are captured verbatim (not parsed); the END keyword is the first
// whole-word, case-insensitive occurrence of ENDCG/ENDHLSL/ENDGLSL, even inside a program
// comment, as in Unity. Every error carries path:line:col through |file| (1-based, columns in
// bytes). Parsing stops at the first error, so there are no follow-on errors; the function
// returns nullopt after reporting at least one error and never reports one on success.
//
// Scoping rules where Unity's documentation is silent:
//  * *INCLUDE blocks apply to every pass in their scope (Shader, Category, SubShader or Pass),
//    including passes written before the block; Pass::includeBlocks lists them in file order.
//  * Render state and Tags/LOD of a Category, and render state of a SubShader, apply to all
//    enclosed passes/subshaders wherever they are written in the block.
//  * A SubShader's (or its Category's) `LightMode` tag applies to each of its passes that sets
//    none (Unity's compiled shaders list a SubShader's tags among each pass's); a pass's own
//    wins. varc acts on no other pass tag, so no other SubShader tag is copied.
//  * `GrabPass { ... }` is accepted and skipped; `UsePass` yields a Pass with only `usePass`.
//  * Legacy fixed-function commands (Lighting, Material, SetTexture, Fog, ...) are skipped.
//
// Example:
//   Shader "A" { SubShader { Pass { Tags { "LightMode"="ForwardAdd" } Blend One One
//                                   CGPROGRAM ... ENDCG } } }
//   -> one SubShader with one Pass, lightMode() == "ForwardAdd", state.blend = {One, One}.
// Error example: `Shader "A" { Pass {} }` -> "1:14: unknown ShaderLab command 'Pass'".
std::optional<ShaderFile> parseShaderLab(std::string_view text, FileId file, DiagnosticSink& sink);

}  // namespace varc::shaderlab
