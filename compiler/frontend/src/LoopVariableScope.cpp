// SPDX-License-Identifier: Apache-2.0
#include "varc/frontend/LoopVariableScope.h"

#include <algorithm>
#include <map>
#include <optional>
#include <utility>

#include "pruner/ShaderTokenizer.h"

namespace varc::frontend {

namespace {

using pruner::Token;
using pruner::TokenKind;

// A variable declared in a `for` header: `for ( T name = ...` with one declarator.
struct LoopDeclaration {
    size_t forToken = 0;
    size_t typeToken = 0;
    std::string_view type, name;
};

class LoopScopes {
public:
    explicit LoopScopes(const pruner::ShaderTokenizer& tokenizer)
        : mTokenizer(tokenizer), mTokens(tokenizer.tokens()) {
        markBlocks();
    }

    std::string rewrite(std::string_view text, const std::vector<std::string>& names) {
        // (block, name) -> the header declarations in that block, in order.
        std::map<std::pair<size_t, std::string_view>, std::vector<LoopDeclaration>> byBlock;
        for (size_t i = 0; i + 4 < mTokens.size(); ++i) {
            std::optional<LoopDeclaration> declaration = loopDeclarationAt(i);
            if (!declaration) continue;
            if (std::find(names.begin(), names.end(), declaration->name) == names.end()) continue;
            byBlock[{mBlock[i], declaration->name}].push_back(*declaration);
        }
        std::vector<std::pair<size_t, std::pair<size_t, std::string>>> edits;  // offset, (len, text)
        for (const auto& [scope, declarations] : byBlock) {
            if (declaredOutsideLoopHeaders(scope.first, scope.second)) continue;
            const LoopDeclaration& first = declarations.front();
            edits.push_back({offsetOf(statementStart(first.forToken)),
                             {0, std::string(first.type) + " " + std::string(first.name) + "; "}});
            for (const LoopDeclaration& declaration : declarations) {
                if (declaration.type != first.type) continue;
                edits.push_back({offsetOf(declaration.typeToken), {declaration.type.size(), ""}});
            }
        }
        std::string result(text);
        std::sort(edits.begin(), edits.end(),
                  [](const auto& a, const auto& b) { return a.first > b.first; });
        for (const auto& [offset, edit] : edits) result.replace(offset, edit.first, edit.second);
        return result;
    }

private:
    bool is(size_t i, char c) const {
        return i < mTokens.size() && mTokens[i].kind == TokenKind::Punct && mTokens[i].text[0] == c;
    }
    bool isIdentifier(size_t i) const {
        return i < mTokens.size() && mTokens[i].kind == TokenKind::Identifier;
    }
    size_t offsetOf(size_t i) const { return mTokenizer.offsetOf(mTokens[i]); }

    // The '{' of the innermost block around every token (npos at file scope).
    void markBlocks() {
        mBlock.assign(mTokens.size(), std::string::npos);
        std::vector<size_t> open;
        for (size_t i = 0; i < mTokens.size(); ++i) {
            if (is(i, '}') && !open.empty()) open.pop_back();
            mBlock[i] = open.empty() ? std::string::npos : open.back();
            if (is(i, '{')) open.push_back(i);
        }
    }

    // The first token of the loop statement at |forToken|: its attributes (`[unroll]`,
    // `[loop]`, `[unroll(4)]`) belong to it, so the declaration goes before them.
    size_t statementStart(size_t forToken) const {
        size_t start = forToken;
        while (start > 0 && is(start - 1, ']')) {
            size_t open = start - 1;
            int depth = 0;
            do {
                if (is(open, ']')) ++depth;
                if (is(open, '[')) --depth;
            } while (depth > 0 && open-- > 0);
            if (depth != 0) break;
            start = open;
        }
        return start;
    }

    std::optional<LoopDeclaration> loopDeclarationAt(size_t i) const {
        if (!isIdentifier(i) || mTokens[i].text != "for" || !is(i + 1, '(')) return std::nullopt;
        if (!isIdentifier(i + 2) || !isIdentifier(i + 3)) return std::nullopt;
        if (!is(i + 4, '=') && !is(i + 4, ';')) return std::nullopt;
        // One declarator only: no ',' at the header's top level before its first ';'.
        int depth = 0;
        for (size_t j = i + 4; j < mTokens.size() && !(depth == 0 && is(j, ';')); ++j) {
            if (is(j, '(') || is(j, '[') || is(j, '{')) ++depth;
            if (is(j, ')') || is(j, ']') || is(j, '}')) --depth;
            if (depth < 0) return std::nullopt;
            if (depth == 0 && is(j, ',')) return std::nullopt;
        }
        return LoopDeclaration{i, i + 2, mTokens[i + 2].text, mTokens[i + 3].text};
    }

    // Whether block |block| declares |name| itself (`T name` followed by = ; , [ or )) other
    // than in a `for` header.
    bool declaredOutsideLoopHeaders(size_t block, std::string_view name) const {
        for (size_t i = 1; i + 1 < mTokens.size(); ++i) {
            if (mBlock[i] != block || !isIdentifier(i) || mTokens[i].text != name) continue;
            if (!isIdentifier(i - 1) || mTokens[i - 1].text == "return") continue;
            bool inLoopHeader = i >= 3 && is(i - 2, '(') && isIdentifier(i - 3) &&
                                mTokens[i - 3].text == "for";
            if (!inLoopHeader) return true;
        }
        return false;
    }

    const pruner::ShaderTokenizer& mTokenizer;
    const std::vector<Token>& mTokens;
    std::vector<size_t> mBlock;
};

}  // namespace

std::string hoistLoopVariables(std::string_view text, const std::vector<std::string>& unknownNames) {
    if (unknownNames.empty() || text.find("for") == std::string_view::npos) {
        return std::string(text);
    }
    pruner::ShaderTokenizer tokenizer;
    if (!tokenizer.tokenize(text)) return std::string(text);
    return LoopScopes(tokenizer).rewrite(text, unknownNames);
}

}  // namespace varc::frontend
