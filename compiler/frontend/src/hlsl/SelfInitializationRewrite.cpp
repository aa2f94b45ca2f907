// SPDX-License-Identifier: Apache-2.0
// Splits a local declaration whose initializer names the variable itself.
//
// HLSL puts a local in scope in its own initializer (uninitialised; FXC warns), glslang does not.
// This rewrite produces `Out o; o = f(o, p);` from `Out o = f(o, p);` for a declaration of one
// identifier type and one declarator, not const or static. It never adds, removes or moves a line
// break, so every `#line` mapping still holds.
#include <set>

#include "HlslRewrite.h"
#include "HlslRewritePasses.h"

namespace varc::frontend::hlsl {

namespace {

using pruner::TokenKind;

class SelfInitializationRewrite : public HlslRewrite {
public:
    explicit SelfInitializationRewrite(RewriteState& state) : HlslRewrite(state) {}

    // `T o = f(o);` in a function body -> `T o; o = f(o);`: HLSL puts a local in scope in its
    // own initializer (uninitialised, fxc warns), glslang does not. Only a declaration that
    // starts a statement, of one identifier type and one declarator, whose initializer names the
    // variable; `const` and `static` declarations (which need their initializer) are left alone.
    void run() {
        static const std::set<std::string_view> kNotType = {"return", "else",   "do",  "case",
                                                            "const",  "static", "goto"};
        for (size_t i = 2; i + 1 < mTokens.size(); ++i) {
            if (mDepth[i] == 0 || mInDeclarationBody[i] || !is(i + 1, '=') ||
                (i + 2 < mTokens.size() && is(i + 2, '=') && adjacent(i + 1, i + 2))) {
                continue;
            }
            if (mTokens[i].kind != TokenKind::Identifier ||
                mTokens[i - 1].kind != TokenKind::Identifier ||
                kNotType.count(mTokens[i - 1].text) ||
                !(is(i - 2, ';') || is(i - 2, '{') || is(i - 2, '}'))) {
                continue;
            }
            if (initializerNames(i + 2, mTokens[i].text)) {
                std::string name(mTokens[i].text);
                mReplacements.push_back({endOf(i), endOf(i + 1) - endOf(i), "; " + name + " ="});
            }
        }
    }

private:
    // Whether the initializer starting at |begin| (up to its ';') uses |name|; false when it
    // has a ',' outside brackets (a further declarator) or never ends.
    bool initializerNames(size_t begin, std::string_view name) const {
        bool named = false;
        int depth = 0;
        for (size_t j = begin; j < mTokens.size(); ++j) {
            if (is(j, '(') || is(j, '[') || is(j, '{')) ++depth;
            if (is(j, ')') || is(j, ']') || is(j, '}')) --depth;
            if (depth < 0) return false;
            if (depth == 0 && is(j, ',')) return false;
            if (depth == 0 && is(j, ';')) return named;
            named = named || (mTokens[j].kind == TokenKind::Identifier && mTokens[j].text == name &&
                              !is(j - 1, '.'));
        }
        return false;
    }
};

}  // namespace

void splitSelfInitializations(RewriteState& state) { SelfInitializationRewrite(state).run(); }

}  // namespace varc::frontend::hlsl
