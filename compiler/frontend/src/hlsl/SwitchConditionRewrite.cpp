// SPDX-License-Identifier: Apache-2.0
// Converts the condition of a switch to int.
//
// FXC accepts `switch (f)` on a float and converts it to int; glslang requires an integer
// condition. This rewrite produces `switch ((int)(f))`, unless a case label carries a `u` suffix
// (the condition is unsigned already). It never adds, removes or moves a line break, so every
// `#line` mapping still holds.
#include "HlslRewrite.h"
#include "HlslRewritePasses.h"

namespace varc::frontend::hlsl {

namespace {

using pruner::TokenKind;

class SwitchConditionRewrite : public HlslRewrite {
public:
    explicit SwitchConditionRewrite(RewriteState& state) : HlslRewrite(state) {}

    void run() {
        for (size_t i = 0; i + 1 < mTokens.size(); ++i) {
            if (!isWord(i, "switch") || !is(i + 1, '(')) continue;
            size_t close = matching(i + 1);
            if (close == std::string::npos || close + 1 >= mTokens.size() || !is(close + 1, '{')) {
                continue;
            }
            size_t bodyEnd = matching(close + 1);
            if (bodyEnd == std::string::npos || hasUnsignedCase(close + 1, bodyEnd)) continue;
            mInsertions.push_back({endOf(i + 1), "(int)("});
            mInsertions.push_back({offsetOf(close), ")"});
        }
    }

private:
    bool hasUnsignedCase(size_t begin, size_t end) const {
        for (size_t i = begin; i + 1 < end; ++i) {
            if (!isWord(i, "case") || mTokens[i + 1].kind != TokenKind::Number) continue;
            char last = mTokens[i + 1].text.back();
            if (last == 'u' || last == 'U') return true;
        }
        return false;
    }
};

}  // namespace

void castSwitchConditions(RewriteState& state) { SwitchConditionRewrite(state).run(); }

}  // namespace varc::frontend::hlsl
