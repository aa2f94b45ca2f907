// SPDX-License-Identifier: Apache-2.0
// Gives a uniform that the code writes a static copy that the code uses instead.
//
// FXC treats a written non-static, non-const global (or file-scope cbuffer member) as a per-
// invocation copy initialised from the uniform; glslang refuses to write a uniform. This rewrite
// declares ` static float _S_varcCopy = _S;` after the declaration (after the cbuffer's closing
// brace for a member), on the same line, and renames every other use to the copy; the uniform keeps
// its name for reflection. Arrays and initialised declarations are left alone. It never adds,
// removes or moves a line break, so every `#line` mapping still holds.
#include <set>

#include "HlslRewrite.h"
#include "HlslRewritePasses.h"

namespace varc::frontend::hlsl {

namespace {

using pruner::TokenKind;

class WrittenUniformCopyRewrite : public HlslRewrite {
public:
    explicit WrittenUniformCopyRewrite(RewriteState& state) : HlslRewrite(state) {}

    void run() {
        for (const Declarator& uniform : looseUniforms()) {
            std::string_view name = mTokens[uniform.nameToken].text;
            bool written = false;
            for (size_t i = 0; i < mTokens.size() && !written; ++i) {
                written = mDepth[i] > 0 && isUse(i, name) && isWrite(i);
            }
            if (!written) continue;
            std::string copy = std::string(name) + "_varcCopy";
            mInsertions.push_back(
                {endOf(uniform.copyAfter),
                 " static " + uniform.type + " " + copy + " = " + std::string(name) + ";"});
            for (size_t i = 0; i < mTokens.size(); ++i) {
                if (i >= uniform.statementBegin && i <= uniform.statementEnd) continue;
                if (isUse(i, name)) mReplacements.push_back({offsetOf(i), name.size(), copy});
            }
        }
    }

private:
    // A ';' at file scope, or a brace opening or closing a file-scope body (mDepth counts the
    // brace itself as inside).
    bool endsTopLevelStatement(size_t i) const {
        return (is(i, ';') && mDepth[i] == 0) || ((is(i, '{') || is(i, '}')) && mDepth[i] == 1);
    }

    // A uniform declarator: `[uniform] Type name {, name};` at file scope or in a cbuffer.
    struct Declarator {
        size_t nameToken = 0;
        size_t statementBegin = 0, statementEnd = 0;  // first token and the ';'
        size_t copyAfter = 0;                         // the token after which the copy is declared
        std::string type;
    };

    std::vector<Declarator> looseUniforms() const {
        static const std::set<std::string_view> kNotUniform = {
            "static",  "const",       "struct", "typedef", "cbuffer",
            "tbuffer", "groupshared", "extern", "return",  "namespace",
            "class",   "interface",   "in",     "out",     "inout"};
        std::vector<Declarator> found;
        size_t start = 0;
        for (size_t i = 0; i < mTokens.size(); ++i) {
            if (!endsTopLevelStatement(i)) continue;
            if (is(i, ';') && i > start) collectDeclarators(start, i, 0, i, kNotUniform, found);
            start = i + 1;
        }
        // cbuffer members: Unity declares its built-ins (_LightColor0, ...) as loose globals,
        // which shaders may write; varc's library groups them in cbuffers.
        for (const auto& [open, close] : mCbufferBodies) {
            size_t copyAfter = is(close + 1, ';') ? close + 1 : close;
            size_t begin = open + 1;
            for (size_t i = open + 1; i < close; ++i) {
                if (!is(i, ';') || mDepth[i] != 1) continue;
                if (i > begin) collectDeclarators(begin, i, 1, copyAfter, kNotUniform, found);
                begin = i + 1;
            }
        }
        return found;
    }

    void collectDeclarators(size_t begin, size_t end, int depth, size_t copyAfter,
                            const std::set<std::string_view>& excluded,
                            std::vector<Declarator>& found) const {
        for (size_t i = begin; i < end; ++i) {
            if (is(i, '(') || is(i, '=') || is(i, '[') || is(i, '<') || is(i, ':')) return;
            if (mTokens[i].kind == TokenKind::Identifier && excluded.count(mTokens[i].text)) return;
            if (mDepth[i] != depth) return;
        }
        size_t typeBegin = isWord(begin, "uniform") ? begin + 1 : begin;
        // Type tokens run up to the first name followed by ',' or ';'.
        size_t first = typeBegin + 1;
        if (first >= end || mTokens[typeBegin].kind != TokenKind::Identifier) return;
        while (first < end && !(mTokens[first].kind == TokenKind::Identifier &&
                                (is(first + 1, ',') || first + 1 == end))) {
            ++first;
        }
        if (first >= end) return;
        std::string type(
            mTokenizer.code().substr(offsetOf(typeBegin), endOf(first - 1) - offsetOf(typeBegin)));
        if (type.rfind("sampler", 0) == 0 || type.rfind("Texture", 0) == 0 ||
            type.rfind("SamplerState", 0) == 0 || type.rfind("SamplerComparisonState", 0) == 0 ||
            type.find("Buffer") != std::string::npos) {
            return;  // resources are not $Global members
        }
        for (size_t i = first; i < end; i += 2) {
            if (mTokens[i].kind != TokenKind::Identifier) return;
            found.push_back({i, begin, end, copyAfter, type});
            if (i + 1 < end && !is(i + 1, ',')) return;
        }
    }

    bool isUse(size_t i, std::string_view name) const {
        return mTokens[i].kind == TokenKind::Identifier && mTokens[i].text == name &&
               !mInDeclarationBody[i] && !(i > 0 && is(i - 1, '.'));
    }
};

}  // namespace

void copyWrittenUniforms(RewriteState& state) { WrittenUniformCopyRewrite(state).run(); }

}  // namespace varc::frontend::hlsl
