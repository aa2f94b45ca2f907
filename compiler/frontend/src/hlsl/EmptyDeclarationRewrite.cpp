// SPDX-License-Identifier: Apache-2.0
// Blanks the empty declarations that macros expanding to nothing leave behind.
//
// FXC skips an empty declaration (`float a;;`, `{ ;`) in a struct, a cbuffer or at file scope;
// glslang refuses it. This rewrite replaces the lone `;` by a space (a `;` after a file-scope `}`
// ends a struct or cbuffer and stays). It never adds, removes or moves a line break, so every
// `#line` mapping still holds.
#include "HlslRewrite.h"
#include "HlslRewritePasses.h"

namespace varc::frontend::hlsl {

namespace {

using pruner::TokenKind;

class EmptyDeclarationRewrite : public HlslRewrite {
public:
    explicit EmptyDeclarationRewrite(RewriteState& state) : HlslRewrite(state) {}

    // Declaration macros that expand to nothing leave empty declarations (`float a;;`, `{ ;`)
    // in structs, cbuffers and at file scope, which the DirectX compilers skip and glslang
    // refuses. (A `;` after a file-scope `}` ends a struct or cbuffer and stays.)
    void run() {
        for (size_t i = 1; i < mTokens.size(); ++i) {
            if (!is(i, ';')) continue;
            bool inBody = mInDeclarationBody[i] && mDepth[i] > 0;
            bool empty =
                inBody ? (is(i - 1, ';') || is(i - 1, '{')) : (mDepth[i] == 0 && is(i - 1, ';'));
            if (empty) mReplacements.push_back({offsetOf(i), 1, " "});
        }
    }
};

}  // namespace

void dropEmptyMemberDeclarations(RewriteState& state) { EmptyDeclarationRewrite(state).run(); }

}  // namespace varc::frontend::hlsl
