// SPDX-License-Identifier: Apache-2.0
// Syntax shared by Shader, Category, SubShader and Pass bodies: Tags, LOD and block loops.
#pragma once

#include <string_view>

#include "IncludeScopes.h"
#include "lex/TokenCursor.h"
#include "varc/shaderlab/ShaderAst.h"

namespace varc::shaderlab {

// Parses `{ "Key" = "Value" ... }` after the `Tags` keyword, appending to |tags| (a key written
// again replaces the earlier value). Example: `{ "LightMode" = "ForwardBase" }`.
bool parseTags(TokenCursor& cursor, Tags& tags);

// Parses the integer after the `LOD` keyword into |lod|: `LOD 200`, `LOD -10` (Unity accepts
// negative levels).
bool parseLod(TokenCursor& cursor, int& lod);

// Calls |parseItem| (which consumes one item, or reports and returns false) until the '}'
// closing |openBrace|, which it consumes. Reports "'{' opened here is never closed" at
// |openBrace| at end of file.
template <typename ItemParser>
bool parseBlockItems(TokenCursor& cursor, const Token& openBrace, ItemParser&& parseItem) {
    while (true) {
        BlockStep step = cursor.blockStep(openBrace);
        if (step == BlockStep::End) return true;
        if (step == BlockStep::Failed) return false;
        if (!parseItem()) return false;
    }
}

// Reports the right error for the unexpected next token at a command position in |scope|
// ("Pass", "SubShader", ...): "unknown ShaderLab command 'Foo'" for identifiers, else
// "expected a command or '}' in Pass, found ...". Always returns false.
bool reportUnexpectedCommand(TokenCursor& cursor, std::string_view scope);

// At a command position whose next token is a program keyword: captures a *INCLUDE block into
// the innermost scope of |scopes|. A program block (CGPROGRAM, ...) is reported as
// "CGPROGRAM block must be inside a Pass" (one with `#pragma surface`: "must be written
// directly inside a SubShader"); Pass and SubShader bodies handle those themselves.
bool parseIncludeBlock(TokenCursor& cursor, IncludeScopes& scopes);

}  // namespace varc::shaderlab
