// SPDX-License-Identifier: Apache-2.0
// findUnnamedEntryParameter: one pass over the tokens of a preprocessed HLSL program.
#include "varc/frontend/EntryPointCheck.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <vector>

#include "pruner/ShaderTokenizer.h"

namespace varc::frontend {

namespace {

using pruner::Token;
using pruner::TokenKind;

// Words that qualify a parameter without naming it.
constexpr std::array<std::string_view, 16> kModifiers = {
    "in",     "out",      "inout",           "uniform",       "const",  "precise",
    "linear", "centroid", "nointerpolation", "noperspective", "sample", "point",
    "line",   "triangle", "lineadj",         "triangleadj"};

bool isModifier(std::string_view word) {
    return std::find(kModifiers.begin(), kModifiers.end(), word) != kModifiers.end();
}

// The index of the token that closes the bracket opened at |open|, or |end| when unbalanced.
size_t matching(const std::vector<Token>& tokens, size_t open, size_t end) {
    const char opener = tokens[open].text[0];
    const char closer = opener == '(' ? ')' : opener == '[' ? ']' : '>';
    int depth = 0;
    for (size_t i = open; i < end; ++i) {
        if (tokens[i].kind != TokenKind::Punct) continue;
        if (tokens[i].text[0] == opener) ++depth;
        if (tokens[i].text[0] == closer && --depth == 0) return i;
    }
    return end;
}

// Whether tokens [begin, end) (one parameter, semantics and defaults excluded) name something:
// at least two words besides modifiers, template arguments and array sizes (type, name).
bool namesTheParameter(const std::vector<Token>& tokens, size_t begin, size_t end) {
    size_t words = 0;
    for (size_t i = begin; i < end; ++i) {
        const Token& token = tokens[i];
        if (token.kind == TokenKind::Punct && (token.text == "<" || token.text == "[")) {
            i = matching(tokens, i, end);
        } else if (token.kind == TokenKind::Identifier && !isModifier(token.text)) {
            ++words;
        }
    }
    return words >= 2;
}

// Maps physical line |line| (0-based) of the tokenized text to (fileId, 1-based line) through
// the last `#line N F` before it: the line after that directive is line N of file F.
void locate(const pruner::ShaderTokenizer& tokenizer, size_t line, UnnamedParameter& out) {
    out.file = 0;
    out.line = line + 1;
    for (const pruner::DirectiveLine& directive : tokenizer.directives()) {
        if (directive.line >= line) break;
        if (!directive.text.starts_with("#line")) continue;
        char* rest = nullptr;
        const char* numbers = directive.text.c_str() + 5;
        unsigned long number = std::strtoul(numbers, &rest, 10);
        if (rest == numbers) continue;
        out.line = number + (line - directive.line - 1);
        out.file = std::strtoul(rest, nullptr, 10);
    }
}

}  // namespace

std::optional<UnnamedParameter> findUnnamedEntryParameter(std::string_view preprocessed,
                                                          std::string_view entry) {
    pruner::ShaderTokenizer tokenizer;
    if (!tokenizer.tokenize(preprocessed)) return std::nullopt;
    const std::vector<Token>& tokens = tokenizer.tokens();
    for (size_t i = 1; i + 1 < tokens.size(); ++i) {
        if (tokens[i].text != entry || tokens[i + 1].text != "(") continue;
        // A definition: a return type before the name, and after the list ':' or '{'.
        if (tokens[i - 1].kind != TokenKind::Identifier && tokens[i - 1].text != ">") continue;
        const size_t close = matching(tokens, i + 1, tokens.size());
        if (close + 1 >= tokens.size()) continue;
        if (tokens[close + 1].text != ":" && tokens[close + 1].text != "{") continue;
        if (close == i + 2 || (close == i + 3 && tokens[i + 2].text == "void")) return std::nullopt;
        size_t begin = i + 2, index = 1;
        for (size_t t = begin; t <= close; ++t) {
            const Token& token = tokens[t];
            if (token.text == "(" || token.text == "<" || token.text == "[") {
                t = matching(tokens, t, close);
                continue;
            }
            if (t != close && token.text != ",") continue;
            // The parameter's declaration ends at its semantic (':') or default ('=').
            size_t end = begin;
            while (end < t && tokens[end].text != ":" && tokens[end].text != "=") ++end;
            if (!namesTheParameter(tokens, begin, end)) {
                UnnamedParameter found;
                found.index = index;
                const size_t from = tokenizer.offsetOf(tokens[begin < t ? begin : t]);
                const size_t to = tokenizer.offsetOf(tokens[t]);
                found.text = tokenizer.code().substr(from, to - from);
                locate(tokenizer, tokens[begin < t ? begin : t].line, found);
                return found;
            }
            begin = t + 1;
            ++index;
        }
        return std::nullopt;
    }
    return std::nullopt;
}

}  // namespace varc::frontend
