// SPDX-License-Identifier: Apache-2.0
// findCbufferRedeclaration: the members of file-scope cbuffers against the file-scope globals.
#include "varc/frontend/CbufferRedeclarations.h"

#include <array>
#include <cstdlib>
#include <map>
#include <vector>

#include "pruner/LineOriginMap.h"
#include "pruner/ShaderTokenizer.h"

namespace varc::frontend {

namespace {

using pruner::Token;
using pruner::TokenKind;

struct Member {
    std::string_view type;
    std::string_view cbuffer;
    bool array = false;  // declared `NAME[...]`
};

// |type| with its float precision spelled `float` ("half4" -> "float4", "fixed3x3" ->
// "float3x3"); other types unchanged.
std::string shapeOf(std::string_view type) {
    constexpr std::array<std::string_view, 4> kPrecisions = {"min16float", "min10float", "half",
                                                             "fixed"};
    for (std::string_view precision : kPrecisions) {
        if (type.starts_with(precision))
            return "float" + std::string(type.substr(precision.size()));
    }
    return std::string(type);
}

// |type| as a redeclaration is compared and reported: its shape, "[]" after an array's.
std::string displayOf(std::string_view type, bool array) {
    return std::string(type) + (array ? "[]" : "");
}

// Whether tokens[i], tokens[i + 1] are the type and name of a variable declaration:
// `TYPE NAME` followed by ';', ':', '[' or '=' (not a function's '(').
bool isDeclaration(const std::vector<Token>& tokens, size_t i) {
    if (i + 2 >= tokens.size()) return false;
    if (tokens[i].kind != TokenKind::Identifier || tokens[i + 1].kind != TokenKind::Identifier)
        return false;
    std::string_view next = tokens[i + 2].text;
    return next == ";" || next == ":" || next == "[" || next == "=";
}

// The members of every file-scope `cbuffer NAME { ... }`, by name.
std::map<std::string_view, Member> cbufferMembers(const std::vector<Token>& tokens) {
    std::map<std::string_view, Member> members;
    int depth = 0;
    for (size_t i = 0; i < tokens.size(); ++i) {
        if (tokens[i].text == "{") ++depth;
        if (tokens[i].text == "}") --depth;
        if (depth != 0 || tokens[i].text != "cbuffer" || i + 2 >= tokens.size() ||
            tokens[i + 2].text != "{")
            continue;
        size_t t = i + 3;
        for (; t < tokens.size() && tokens[t].text != "}"; ++t) {
            if (isDeclaration(tokens, t) && (t == i + 3 || tokens[t - 1].text == ";"))
                members.emplace(tokens[t + 1].text, Member{tokens[t].text, tokens[i + 1].text,
                                                           tokens[t + 2].text == "["});
        }
        i = t;  // the closing brace: depth stays 0
    }
    return members;
}

}  // namespace

std::optional<CbufferRedeclaration> findCbufferRedeclaration(std::string_view preprocessed) {
    pruner::ShaderTokenizer tokenizer;
    if (!tokenizer.tokenize(preprocessed)) return std::nullopt;
    const std::vector<Token>& tokens = tokenizer.tokens();
    // Cbuffer members, then each global as it is first declared (an empty cbuffer name).
    std::map<std::string_view, Member> members = cbufferMembers(tokens);
    int depth = 0;
    for (size_t i = 0; i < tokens.size(); ++i) {
        if (tokens[i].text == "{") ++depth;
        if (tokens[i].text == "}") --depth;
        if (depth != 0 || !isDeclaration(tokens, i)) continue;
        if (i > 0 && tokens[i - 1].text != ";" && tokens[i - 1].text != "}" &&
            tokens[i - 1].kind != TokenKind::Identifier)
            continue;  // not the start of a declaration (e.g. after '(' or ',')
        const bool array = tokens[i + 2].text == "[";
        auto member = members.find(tokens[i + 1].text);
        if (member == members.end()) {
            members.emplace(tokens[i + 1].text, Member{tokens[i].text, {}, array});
            continue;
        }
        // An array and a plain variable of one name differ in shape too (`float4 _A;` then
        // `float4 _A[...`, even a malformed one, reaches the same crash).
        if (shapeOf(member->second.type) == shapeOf(tokens[i].text) &&
            member->second.array == array)
            continue;
        CbufferRedeclaration found{std::string(tokens[i + 1].text),
                                   displayOf(tokens[i].text, array),
                                   displayOf(member->second.type, member->second.array),
                                   std::string(member->second.cbuffer),
                                   0,
                                   0};
        const size_t line = tokens[i].line;
        found.line = line + 1;
        pruner::LineOriginMap origins;
        if (origins.build(tokenizer.directives(), line + 1)) {
            const pruner::LineOrigin& origin = origins.origin(line);
            found.line = origin.line;
            if (origin.hasSource)
                found.file = std::strtoul(std::string(origin.source).c_str(), nullptr, 10);
        }
        return found;
    }
    return std::nullopt;
}

}  // namespace varc::frontend
