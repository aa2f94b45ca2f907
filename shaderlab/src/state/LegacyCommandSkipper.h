// SPDX-License-Identifier: Apache-2.0
// Accepts and discards legacy fixed-function commands (Lighting, Material, SetTexture, Fog, ...).
#pragma once

#include "lex/Token.h"
#include "lex/TokenCursor.h"

namespace varc::shaderlab {

// varc compiles programmable passes only, so these commands have no effect, but shaders that
// still carry them must parse:
//   Lighting On|Off          SeparateSpecular [On|Off]     ColorMaterial AmbientAndDiffuse|Emission
//   Material { ... }         Fog { ... }                   BindChannels { ... }
//   SetTexture [_X] { ... }  AlphaTest Off | AlphaTest <comparison> [value|[_Prop]]
class LegacyCommandSkipper {
public:
    explicit LegacyCommandSkipper(TokenCursor& cursor) : mCursor(cursor) {}

    // True when |token| names one of the commands above.
    static bool isLegacyCommand(const Token& token);

    // Consumes the legacy command at the cursor (isLegacyCommand(peek()) must hold) and its
    // arguments. Reports malformed arguments ("expected '{' after Material, found 'On'").
    bool skip();

private:
    bool skipWord(const Token& keyword, bool required);
    bool skipBlock(const Token& keyword);
    bool skipSetTexture(const Token& keyword);
    bool skipAlphaTest();

    TokenCursor& mCursor;
};

}  // namespace varc::shaderlab
