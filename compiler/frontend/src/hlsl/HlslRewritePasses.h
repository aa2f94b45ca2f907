// SPDX-License-Identifier: Apache-2.0
// The HLSL rewrites, one per file under hlsl/ (see each file for its contract), as functions.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "HlslRewrite.h"

namespace varc::frontend::hlsl {

// Fills |state|.depth, inDeclarationBody and cbufferBodies; run before the rewrites below.
void scanDeclarationBodies(RewriteState& state);

// Casts the arguments of every call of |function| to its parameter types (one signature only).
void castCallArguments(RewriteState& state, std::string_view function);

// `switch (f)` -> `switch ((int)(f))`, unless a case label is unsigned.
void castSwitchConditions(RewriteState& state);

// Declares a `<name>_varcCopy` of each uniform the code writes and renames its uses.
void copyWrittenUniforms(RewriteState& state);

// Declares a `<name>_varcCopy` local of each `uniform` parameter the body writes.
void copyWrittenUniformParameters(RewriteState& state);

// Declares `bool any(float v) { return v != 0; }` and the other scalar overloads first.
void declareScalarAnyAll(RewriteState& state);

// `M._m20_m21` -> `float2(M[2][0], M[2][1])` for a matrix named by one identifier.
void spellOutMatrixSwizzles(RewriteState& state);

// `0x1376312589U` -> `0x76312589U` in every number token.
void truncateWideHexTokens(RewriteState& state);

// Blanks the lone `;` of empty member and file-scope declarations.
void dropEmptyMemberDeclarations(RewriteState& state);

// `T o = f(o);` -> `T o; o = f(o);` in function bodies.
void splitSelfInitializations(RewriteState& state);

// Moves resource declarations out of file-scope cbuffers, before the keyword.
void hoistCbufferResources(RewriteState& state);

// `uint facing : SV_IsFrontFace` -> `bool facing : SV_IsFrontFace`.
void makeFrontFaceParametersBool(RewriteState& state);

// `half facing : VFACE` -> an SV_IsFrontFace bool and `half facing = ... ? 1 : -1;`.
void replaceFaceParameters(RewriteState& state);

// The hexadecimal literal at the start of |text| ("0x1376312589U + 1" -> "0x1376312589U"), or "".
std::string_view hexLiteralAt(std::string_view text);

// "0x1376312589U" -> "0x76312589U"; nullopt when |literal| is not a hexadecimal literal of more
// than 32 significant bits.
std::optional<std::string> truncatedHexLiteral(std::string_view literal);

}  // namespace varc::frontend::hlsl
