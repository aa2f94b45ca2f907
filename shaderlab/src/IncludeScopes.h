// SPDX-License-Identifier: Apache-2.0
// Tracks which *INCLUDE blocks are in scope for which passes while a shader is parsed.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "varc/shaderlab/ShaderAst.h"

namespace varc::shaderlab {

// Scopes are the Shader, Category, SubShader and Pass blocks. An include block belongs to the
// innermost open scope and applies to every pass inside that scope, wherever the pass is
// written relative to the block. Example:
//   Shader { SubShader { Pass {A} CGINCLUDE x ENDCG Pass {B} } }  -> A and B both get x.
class IncludeScopes {
public:
    void enter();
    void leave();
    // Adds |block| to the innermost open scope.
    void addInclude(ProgramBlock block);
    // Records that subShaders[|subShader|].passes[|pass|] sits in the currently open scopes.
    void addPass(size_t subShader, size_t pass);
    // Fills Pass::includeBlocks of every recorded pass, in file order.
    void assignTo(ShaderFile& shader) const;

private:
    struct PassScopes {
        size_t subShader;
        size_t pass;
        std::vector<size_t> scopes;  // ids of the enclosing scopes, outermost first
    };

    std::vector<size_t> mOpen;  // ids of the open scopes, outermost first
    size_t mNextId = 0;
    std::vector<std::pair<size_t, ProgramBlock>> mIncludes;  // (scope id, block), file order
    std::vector<PassScopes> mPasses;
};

}  // namespace varc::shaderlab
