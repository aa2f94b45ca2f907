// SPDX-License-Identifier: Apache-2.0
// Declares every SV_IsFrontFace parameter bool.
//
// FXC accepts `uint facing : SV_IsFrontFace`; Vulkan's FrontFacing is a bool and glslang passes any
// other type through into invalid SPIR-V. This rewrite replaces the type by `bool`. It never adds,
// removes or moves a line break, so every `#line` mapping still holds.
#include "HlslRewrite.h"
#include "HlslRewritePasses.h"

namespace varc::frontend::hlsl {

namespace {

using pruner::TokenKind;

class FrontFaceBoolRewrite : public HlslRewrite {
public:
    explicit FrontFaceBoolRewrite(RewriteState& state) : HlslRewrite(state) {}

    // `uint facing : SV_IsFrontFace` -> `bool facing : SV_IsFrontFace`: Vulkan's FrontFacing is a
    // bool, and glslang passes any other type through into invalid SPIR-V.
    void run() {
        for (size_t i = 3; i < mTokens.size(); ++i) {
            if (mTokens[i].text != "SV_IsFrontFace" || !is(i - 1, ':')) continue;
            size_t type = i - 3;
            if (mTokens[type].kind != TokenKind::Identifier || mTokens[type].text == "bool")
                continue;
            mReplacements.push_back({offsetOf(type), mTokens[type].text.size(), "bool"});
        }
    }
};

}  // namespace

void makeFrontFaceParametersBool(RewriteState& state) { FrontFaceBoolRewrite(state).run(); }

}  // namespace varc::frontend::hlsl
