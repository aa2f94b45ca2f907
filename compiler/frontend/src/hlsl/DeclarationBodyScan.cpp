// SPDX-License-Identifier: Apache-2.0
// Marks brace depth, struct/cbuffer bodies and file-scope cbuffers for the other rewrites.
//
// Not a rewrite but the scan the others read: the brace depth of every token, whether it lies in a
// struct or cbuffer body (where names are members, not uses), and the '{' and '}' of every file-
// scope cbuffer. Collects no edit, so it moves no line.
#include "HlslRewrite.h"
#include "HlslRewritePasses.h"

namespace varc::frontend::hlsl {

namespace {

using pruner::TokenKind;

class DeclarationBodyScan : public HlslRewrite {
public:
    explicit DeclarationBodyScan(RewriteState& state) : HlslRewrite(state) {}

    // Brace depth of every token, and whether it lies in a struct or cbuffer body, where names
    // are members rather than uses.
    void run() {
        mDepth.assign(mTokens.size(), 0);
        mInDeclarationBody.assign(mTokens.size(), false);
        std::vector<bool> bodyStack;
        bool pendingBody = false, pendingCbuffer = false;
        size_t cbufferOpen = std::string::npos;
        int depth = 0;
        for (size_t i = 0; i < mTokens.size(); ++i) {
            if (isWord(i, "struct") || isWord(i, "cbuffer") || isWord(i, "tbuffer")) {
                pendingBody = true;
                pendingCbuffer = isWord(i, "cbuffer") && depth == 0;
            }
            if (is(i, ';') || is(i, '(')) pendingBody = pendingCbuffer = false;
            if (is(i, '{')) {
                bodyStack.push_back(pendingBody || (!bodyStack.empty() && bodyStack.back()));
                if (pendingCbuffer) cbufferOpen = i;
                pendingBody = pendingCbuffer = false;
                ++depth;
            }
            mDepth[i] = depth;
            mInDeclarationBody[i] = !bodyStack.empty() && bodyStack.back();
            if (is(i, '}') && depth > 0) {
                if (depth == 1 && cbufferOpen != std::string::npos) {
                    mCbufferBodies.push_back({cbufferOpen, i});
                    cbufferOpen = std::string::npos;
                }
                --depth;
                bodyStack.pop_back();
            }
        }
    }
};

}  // namespace

void scanDeclarationBodies(RewriteState& state) { DeclarationBodyScan(state).run(); }

}  // namespace varc::frontend::hlsl
