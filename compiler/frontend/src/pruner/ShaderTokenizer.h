// SPDX-License-Identifier: Apache-2.0
// Splits preprocessed HLSL/GLSL into tokens, whole-line directives and comment-free line text.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace varc::frontend::pruner {

enum class TokenKind { Identifier, Number, String, Punct };

struct Token {
    TokenKind kind = TokenKind::Punct;
    std::string_view text;  // points into ShaderTokenizer::code()
    size_t line = 0;        // 0-based physical line
};

struct DirectiveLine {
    size_t line = 0;   // 0-based physical line
    std::string text;  // the whole line without surrounding whitespace, e.g. "#line 12 3"
};

// Owns a comment-free copy of its input; tokens point into it, so the tokenizer is neither
// copied nor moved.
class ShaderTokenizer {
public:
    ShaderTokenizer() = default;
    ShaderTokenizer(const ShaderTokenizer&) = delete;
    ShaderTokenizer& operator=(const ShaderTokenizer&) = delete;

    // Tokenizes |text|. A line whose first non-blank character is `#` is a directive: it is
    // recorded whole and produces no tokens. Comments become spaces (newlines kept), so code()
    // has the same lines and offsets as |text|. Punctuation is one character per token; numbers
    // include suffixes and exponents; string literals are one token.
    // Returns false on an unterminated block comment or string literal.
    // Example: "float4 x; // c\n#pragma p\ny = .5f;" gives tokens `float4` `x` `;` (line 0),
    // `y` `=` `.5f` `;` (line 2) and the directive {1, "#pragma p"}.
    bool tokenize(std::string_view text);

    const std::vector<Token>& tokens() const { return mTokens; }
    const std::vector<DirectiveLine>& directives() const { return mDirectives; }
    const std::string& code() const { return mCode; }
    size_t lineCount() const { return mLineStarts.size(); }
    // Offsets into code() of line |line|'s first character and of its end (the '\n' or the end).
    size_t lineBegin(size_t line) const { return mLineStarts[line]; }
    size_t lineEnd(size_t line) const;
    size_t offsetOf(const Token& token) const {
        return static_cast<size_t>(token.text.data() - mCode.data());
    }

private:
    bool blankCommentsAndDirectives();
    size_t skipString(size_t begin) const;
    void recordDirective(size_t begin, size_t end);
    void scanTokens();
    size_t scanNumber(size_t begin) const;

    std::string mCode;
    std::vector<size_t> mLineStarts;
    std::vector<Token> mTokens;
    std::vector<DirectiveLine> mDirectives;
};

}  // namespace varc::frontend::pruner
