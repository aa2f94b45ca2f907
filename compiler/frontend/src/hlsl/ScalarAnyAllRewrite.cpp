// SPDX-License-Identifier: Apache-2.0
// Declares scalar overloads of any() and all() that compare with zero.
//
// FXC takes `any(x)` and `all(x)` of a scalar as `x != 0`; glslang converts the scalar to bool
// and emits OpAny or OpAll on it, which SPIR-V allows on bool vectors only (the validator says
// "Expected operand to be vector bool"). Vectors are fine in glslang (it compares each component
// with zero first), and which call has a scalar argument cannot be told from the text, so this
// rewrite adds overloads for every scalar type, which glslang prefers to its intrinsic for a
// scalar argument and never picks for a vector:
// `bool any(float v) { return v != 0; }` and so on, before the program's first token, on that
// token's line. It never adds, removes or moves a line break, so every `#line` mapping still
// holds.
#include "HlslRewrite.h"
#include "HlslRewritePasses.h"

namespace varc::frontend::hlsl {

namespace {

class ScalarAnyAllRewrite : public HlslRewrite {
public:
    explicit ScalarAnyAllRewrite(RewriteState& state) : HlslRewrite(state) {}

    void run() {
        if (mTokens.empty()) return;
        std::string overloads;
        for (const char* function : {"any", "all"}) {
            for (const char* type : {"bool", "int", "uint", "float"}) {
                overloads += "bool " + std::string(function) + "(" + type + " v) { return v" +
                             (std::string_view(type) == "bool" ? "" : " != 0") + "; } ";
            }
        }
        mInsertions.push_back({offsetOf(0), overloads});
    }
};

}  // namespace

void declareScalarAnyAll(RewriteState& state) { ScalarAnyAllRewrite(state).run(); }

}  // namespace varc::frontend::hlsl
