// SPDX-License-Identifier: Apache-2.0
// Replaces a Direct3D 9 VFACE parameter by an SV_IsFrontFace bool and a local float.
//
// FXC accepts `half facing : VFACE` (positive on front faces, negative on back faces); glslang
// takes VFACE for an interpolator. This rewrite produces `bool facing_varcFrontFace :
// SV_IsFrontFace` and starts the function body, on the line of its `{`, with `half facing =
// facing_varcFrontFace ? 1 : -1;`. It never adds, removes or moves a line break, so every `#line`
// mapping still holds.
#include "HlslRewrite.h"
#include "HlslRewritePasses.h"

namespace varc::frontend::hlsl {

namespace {

using pruner::TokenKind;

class FaceParameterRewrite : public HlslRewrite {
public:
    explicit FaceParameterRewrite(RewriteState& state) : HlslRewrite(state) {}

    // `float4 f(v2f i, half facing : VFACE) : SV_Target { ... }` ->
    // `float4 f(v2f i, bool facing_varcFrontFace : SV_IsFrontFace) : SV_Target { half facing =
    // facing_varcFrontFace ? 1 : -1; ... }`: the Direct3D 9 face register is a float, positive
    // on front faces and negative on back faces; glslang takes VFACE for an interpolator.
    void run() {
        for (size_t i = 3; i < mTokens.size(); ++i) {
            if (!isWord(i, "VFACE") || !is(i - 1, ':')) continue;
            size_t name = i - 2, type = i - 3;
            if (mTokens[name].kind != TokenKind::Identifier ||
                mTokens[type].kind != TokenKind::Identifier) {
                continue;
            }
            std::string bound = std::string(mTokens[name].text) + "_varcFrontFace";
            mReplacements.push_back(
                {offsetOf(type), endOf(i) - offsetOf(type), "bool " + bound + " : SV_IsFrontFace"});
            size_t body = functionBodyAfterParameter(i);
            if (body == std::string::npos) continue;
            mInsertions.push_back({endOf(body), " " + std::string(mTokens[type].text) + " " +
                                                    std::string(mTokens[name].text) + " = " +
                                                    bound + " ? 1 : -1;"});
        }
    }
};

}  // namespace

void replaceFaceParameters(RewriteState& state) { FaceParameterRewrite(state).run(); }

}  // namespace varc::frontend::hlsl
