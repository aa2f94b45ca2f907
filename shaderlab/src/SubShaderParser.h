// SPDX-License-Identifier: Apache-2.0
// Parses `SubShader { ... }` blocks with their passes, UsePass and GrabPass entries.
#pragma once

#include <vector>

#include "IncludeScopes.h"
#include "lex/Token.h"
#include "lex/TokenCursor.h"
#include "state/RenderStateParser.h"
#include "varc/shaderlab/ShaderAst.h"

namespace varc::shaderlab {

class SubShaderParser {
public:
    SubShaderParser(TokenCursor& cursor, RenderStateParser& stateParser, IncludeScopes& scopes)
        : mCursor(cursor), mStateParser(stateParser), mScopes(scopes) {}

    // Parses the block after |keyword| (`SubShader`, consumed) and appends it to |out|. The
    // SubShader's own render state is applied to its passes (Pass::state holds the state of
    // the pass and SubShader; an enclosing Category adds its own later). Example:
    //   SubShader { Tags { "Queue" = "Geometry" } LOD 200 Cull Off Pass { ZWrite Off } }
    //   -> lod 200, one pass with state {Cull Off, ZWrite Off}.
    bool parse(const Token& keyword, std::vector<SubShader>& out);

private:
    bool parseItem(SubShader& subShader, RenderState& state, size_t index);
    bool parsePass(const Token& keyword, SubShader& subShader, size_t index);
    bool parsePassItem(Pass& pass);
    bool parseIgnoredPassLod();
    bool parseProgram(const Token& keyword, Pass& pass);
    bool parseSurface(const Token& keyword, SubShader& subShader, size_t index);
    bool parseUsePass(const Token& keyword, SubShader& subShader);
    bool parseGrabPass();

    TokenCursor& mCursor;
    RenderStateParser& mStateParser;
    IncludeScopes& mScopes;
};

}  // namespace varc::shaderlab
