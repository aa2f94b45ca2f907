// SPDX-License-Identifier: Apache-2.0
// Parses a `Stencil { Ref n Comp x Pass x ... }` block into a StencilState.
#pragma once

#include <string_view>

#include "lex/Token.h"
#include "lex/TokenCursor.h"
#include "varc/shaderlab/RenderState.h"

namespace varc::shaderlab {

// Entries: Ref, ReadMask, WriteMask (integers 0..255 or `[_Prop]`); Comp, Pass, Fail, ZFail
// (both faces) and their Front/Back forms (one face), each a name, a number or `[_Prop]`.
class StencilParser {
public:
    explicit StencilParser(TokenCursor& cursor) : mCursor(cursor) {}

    // Parses `{ ... }` (the `Stencil` keyword already consumed) into |stencil|, overriding the
    // entries written. Errors: "unknown Stencil command 'Foo'", "invalid Stencil Comp value
    // 'Sometimes'; expected ...". Example: `{ Ref 2 CompBack Equal }` -> ref "2", back.comp
    // "Equal", front.comp unset.
    bool parse(StencilState& stencil);

private:
    bool parseEntry(StencilState& stencil);
    bool parseReference(StateValue& out);
    bool parseByteValue(std::string_view name, StateValue& out);
    bool parseFaceEntry(const Token& key, StencilState& stencil);

    TokenCursor& mCursor;
};

}  // namespace varc::shaderlab
