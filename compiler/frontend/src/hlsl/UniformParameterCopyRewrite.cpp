// SPDX-License-Identifier: Apache-2.0
// Gives a `uniform` function parameter that the body writes a local copy that the body uses.
//
// FXC takes a `uniform` parameter (`float4 frag(v2f i, uniform float4 _Tint)`, a constant the
// application sets) as a global, and lets the code write it like any global: a per-invocation
// copy. glslang makes it a uniform and refuses the write ("can't modify a uniform"). Plain
// parameters, entry-point inputs included, are copies in glslang already and are left alone.
// This rewrite starts the body, on the line of its `{`, with ` float4 _Tint_varcCopy = _Tint;`
// and renames every use of the name in the body to the copy; the parameter keeps its name for
// reflection. Array parameters are left alone. It never adds, removes or moves a line break, so
// every `#line` mapping still holds.
#include "HlslRewrite.h"
#include "HlslRewritePasses.h"

namespace varc::frontend::hlsl {

namespace {

using pruner::TokenKind;

class UniformParameterCopyRewrite : public HlslRewrite {
public:
    explicit UniformParameterCopyRewrite(RewriteState& state) : HlslRewrite(state) {}

    // `float4 f(uniform float4 _T) { _T.x += 1; return _T; }` -> `float4 f(uniform float4 _T)
    // { float4 _T_varcCopy = _T; _T_varcCopy.x += 1; return _T_varcCopy; }`.
    void run() {
        for (size_t i = 1; i + 2 < mTokens.size(); ++i) {
            if (!isWord(i, "uniform") || mDepth[i] != 0 || !(is(i - 1, '(') || is(i - 1, ','))) {
                continue;
            }
            size_t type = i + 1, name = i + 2;
            if (mTokens[type].kind != TokenKind::Identifier ||
                mTokens[name].kind != TokenKind::Identifier ||
                !(is(name + 1, ',') || is(name + 1, ')') || is(name + 1, ':') ||
                  is(name + 1, '='))) {
                continue;  // a template type, an array, or not a parameter
            }
            size_t open = functionBodyAfterParameter(name);
            if (open == std::string::npos) continue;
            size_t close = matching(open);
            if (close == std::string::npos || !writtenIn(open, close, mTokens[name].text)) continue;
            copyInBody(open, close, mTokens[type].text, mTokens[name].text);
        }
    }

private:
    bool isUse(size_t i, std::string_view name) const {
        return mTokens[i].kind == TokenKind::Identifier && mTokens[i].text == name &&
               !(i > 0 && is(i - 1, '.'));
    }

    bool writtenIn(size_t open, size_t close, std::string_view name) const {
        for (size_t i = open + 1; i < close; ++i) {
            if (isUse(i, name) && isWrite(i)) return true;
        }
        return false;
    }

    void copyInBody(size_t open, size_t close, std::string_view type, std::string_view name) {
        std::string copy = std::string(name) + "_varcCopy";
        mInsertions.push_back(
            {endOf(open), " " + std::string(type) + " " + copy + " = " + std::string(name) + ";"});
        for (size_t i = open + 1; i < close; ++i) {
            if (isUse(i, name)) mReplacements.push_back({offsetOf(i), name.size(), copy});
        }
    }
};

}  // namespace

void copyWrittenUniformParameters(RewriteState& state) { UniformParameterCopyRewrite(state).run(); }

}  // namespace varc::frontend::hlsl
