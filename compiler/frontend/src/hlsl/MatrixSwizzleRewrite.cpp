// SPDX-License-Identifier: Apache-2.0
// Spells out matrix swizzles of several elements as vector constructors.
//
// FXC accepts matrix swizzles such as `M._m20_m21_m22` and `M._11_22`; glslang implements single
// elements only. This rewrite produces `float3(M[2][0], M[2][1], M[2][2])` for a matrix named by
// one identifier. Written swizzles stay: glslang accepts a simple assignment to one
// (`M._14_24_34 = v;`), and a compound one (`M._14_24_34 *= -1;`, which glslang refuses: "only
// simple assignment to non-simple matrix swizzle is supported") becomes the simple assignment
// `M._14_24_34 = float3(...) * (-1);`. It never adds, removes or moves a line break, so every
// `#line` mapping still holds.
#include "HlslRewrite.h"
#include "HlslRewritePasses.h"

namespace varc::frontend::hlsl {

namespace {

using pruner::TokenKind;

class MatrixSwizzleRewrite : public HlslRewrite {
public:
    explicit MatrixSwizzleRewrite(RewriteState& state) : HlslRewrite(state) {}

    // `M._m20_m21_m22` -> `float3(M[2][0], M[2][1], M[2][2])` and `M._11_22` ->
    // `float2(M[0][0], M[1][1])` (zero- and one-based element names; row, then column), for a
    // matrix named by one identifier. Single elements (`M._m03`) glslang reads itself.
    void run() {
        for (size_t i = 2; i < mTokens.size(); ++i) {
            if (mTokens[i].kind != TokenKind::Identifier || !is(i - 1, '.') ||
                mTokens[i - 2].kind != TokenKind::Identifier || (i >= 3 && is(i - 3, '.'))) {
                continue;
            }
            std::vector<std::pair<int, int>> elements = matrixElements(mTokens[i].text);
            if (elements.size() < 2) continue;
            std::string matrix(mTokens[i - 2].text);
            std::string text = "float" + std::to_string(elements.size()) + "(";
            for (size_t e = 0; e < elements.size(); ++e) {
                text += (e ? ", " : "") + matrix + "[" + std::to_string(elements[e].first) + "][" +
                        std::to_string(elements[e].second) + "]";
            }
            text += ")";
            if (isWrite(i - 2)) {
                rewriteCompoundAssignment(i, text);
                continue;
            }
            mReplacements.push_back({offsetOf(i - 2), endOf(i) - offsetOf(i - 2), text});
        }
    }

private:
    // The swizzle at |i| is written: `op=` becomes `= <read> op (` ... `)` up to the statement's
    // ';'; a simple `=` (or `++`/`--`, which FXC refuses too) is left as it is.
    void rewriteCompoundAssignment(size_t i, const std::string& read) {
        size_t op = i + 1;
        if (op + 1 >= mTokens.size() || !is(op + 1, '=') || !adjacent(op, op + 1) ||
            mTokens[op].kind != pruner::TokenKind::Punct || mTokens[op].text.size() != 1 ||
            std::string_view("+-*/").find(mTokens[op].text[0]) == std::string_view::npos) {
            return;
        }
        int parens = 0;
        size_t end = op + 2;
        for (; end < mTokens.size(); ++end) {
            if (is(end, '(') || is(end, '[')) ++parens;
            if (is(end, ')') || is(end, ']')) --parens;
            if (parens < 0 || (parens == 0 && is(end, ';'))) break;
        }
        if (end >= mTokens.size() || !is(end, ';')) return;
        mReplacements.push_back({offsetOf(op), endOf(op + 1) - offsetOf(op),
                                 "= " + read + " " + std::string(mTokens[op].text) + " ("});
        mInsertions.push_back({offsetOf(end), ")"});
    }

    // "_m20_m21" -> {(2,0), (2,1)}; "_11_22" -> {(0,0), (1,1)}; anything else -> {}.
    static std::vector<std::pair<int, int>> matrixElements(std::string_view name) {
        std::vector<std::pair<int, int>> elements;
        size_t i = 0;
        while (i < name.size() && elements.size() < 4) {
            if (name[i] != '_') return {};
            bool zeroBased = i + 1 < name.size() && name[i + 1] == 'm';
            size_t digits = i + (zeroBased ? 2 : 1);
            if (digits + 2 > name.size()) return {};
            int row = name[digits] - (zeroBased ? '0' : '1');
            int column = name[digits + 1] - (zeroBased ? '0' : '1');
            if (row < 0 || row > 3 || column < 0 || column > 3) return {};
            elements.emplace_back(row, column);
            i = digits + 2;
        }
        return i == name.size() ? elements : std::vector<std::pair<int, int>>{};
    }
};

}  // namespace

void spellOutMatrixSwizzles(RewriteState& state) { MatrixSwizzleRewrite(state).run(); }

}  // namespace varc::frontend::hlsl
