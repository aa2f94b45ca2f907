// SPDX-License-Identifier: Apache-2.0
// findOpaqueStructMember and combineStructTextureMembers: the members of each `struct NAME { ... }`
// in a preprocessed program.
#include "varc/frontend/OpaqueStructMembers.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <vector>

#include "pruner/LineOriginMap.h"
#include "pruner/ShaderTokenizer.h"

namespace varc::frontend {

namespace {

using pruner::Token;
using pruner::TokenKind;

// Words that qualify a member before its type.
constexpr std::array<std::string_view, 9> kModifiers = {
    "const",    "uniform",         "static",        "precise", "linear",
    "centroid", "nointerpolation", "noperspective", "sample"};

// HLSL's separate texture and sampler objects, the types the texture-sampler transform rewrites
// (Texture2D, Texture2DArray, TextureCube, ... with or without template arguments). Cg's combined
// `sampler2D` is left out: glslang compiles it inside a struct (a sampled image already), and so
// are storage textures (RWTexture2D), which the transform does not touch.
bool isOpaqueType(std::string_view word) {
    constexpr std::array<std::string_view, 11> kTypes = {
        "Texture1D",      "Texture1DArray",        "Texture2D",
        "Texture2DArray", "Texture2DMS",           "Texture2DMSArray",
        "Texture3D",      "TextureCube",           "TextureCubeArray",
        "SamplerState",   "SamplerComparisonState"};
    return std::find(kTypes.begin(), kTypes.end(), word) != kTypes.end();
}

// The opaque member declared by tokens [begin, end) (one declaration, up to its ';'), if any:
// its type is the first word that is not a modifier, its name the next word after the type's
// template arguments.
std::optional<std::pair<size_t, size_t>> opaqueMember(const std::vector<Token>& tokens,
                                                      size_t begin, size_t end) {
    size_t type = begin;
    while (type < end && tokens[type].kind == TokenKind::Identifier &&
           std::find(kModifiers.begin(), kModifiers.end(), tokens[type].text) != kModifiers.end())
        ++type;
    if (type >= end || tokens[type].kind != TokenKind::Identifier) return std::nullopt;
    if (!isOpaqueType(tokens[type].text)) return std::nullopt;
    size_t name = type + 1;
    if (name < end && tokens[name].text == "<") {
        int depth = 0;
        for (; name < end; ++name) {
            if (tokens[name].text == "<") ++depth;
            if (tokens[name].text == ">" && --depth == 0) break;
        }
        ++name;
    }
    if (name >= end || tokens[name].kind != TokenKind::Identifier) return std::nullopt;
    return std::make_pair(type, name);
}

}  // namespace

namespace {

// Calls |visit(structToken, typeToken, nameToken)| for each opaque member of each struct, in
// text order, until it returns false.
template <typename Visit>
void forEachOpaqueMember(const std::vector<Token>& tokens, Visit visit) {
    for (size_t i = 0; i + 2 < tokens.size(); ++i) {
        if (tokens[i].text != "struct" || tokens[i + 1].kind != TokenKind::Identifier ||
            tokens[i + 2].text != "{")
            continue;
        // The struct's body at depth 1: each ';' ends one member declaration.
        int depth = 0;
        size_t begin = i + 3;
        for (size_t t = i + 2; t < tokens.size(); ++t) {
            if (tokens[t].text == "{") ++depth;
            if (tokens[t].text == "}" && --depth == 0) break;
            if (depth != 1 || tokens[t].text != ";") continue;
            if (auto found = opaqueMember(tokens, begin, t)) {
                if (!visit(i + 1, found->first, found->second)) return;
            }
            begin = t + 1;
        }
    }
}

// The combined sampler standing for texture type |type|, or empty.
std::string_view combinedSampler(std::string_view type) {
    if (type == "Texture1D") return "sampler1D";
    if (type == "Texture2D") return "sampler2D";
    if (type == "Texture3D") return "sampler3D";
    if (type == "TextureCube") return "samplerCUBE";
    return {};
}

}  // namespace

std::optional<OpaqueStructMember> findOpaqueStructMember(std::string_view preprocessed) {
    pruner::ShaderTokenizer tokenizer;
    if (!tokenizer.tokenize(preprocessed)) return std::nullopt;
    const std::vector<Token>& tokens = tokenizer.tokens();
    std::optional<OpaqueStructMember> member;
    forEachOpaqueMember(tokens, [&](size_t structName, size_t type, size_t name) {
        member.emplace();
        member->structName = std::string(tokens[structName].text);
        member->type = std::string(tokens[type].text);
        member->member = std::string(tokens[name].text);
        pruner::LineOriginMap origins;
        const size_t line = tokens[name].line;
        member->line = line + 1;
        if (origins.build(tokenizer.directives(), line + 1)) {
            const pruner::LineOrigin& origin = origins.origin(line);
            member->line = origin.line;
            if (origin.hasSource)
                member->file = std::strtoul(std::string(origin.source).c_str(), nullptr, 10);
        }
        return false;
    });
    return member;
}

std::string combineStructTextureMembers(std::string_view preprocessed) {
    pruner::ShaderTokenizer tokenizer;
    if (!tokenizer.tokenize(preprocessed)) return std::string(preprocessed);
    const std::vector<Token>& tokens = tokenizer.tokens();
    // Offsets into the tokenizer's code() are the input's: comments become blanks there.
    std::string text(preprocessed);
    forEachOpaqueMember(tokens, [&](size_t, size_t type, size_t name) {
        // Each sampler type is as long as its texture type, so the offsets stay valid.
        std::string_view sampler = combinedSampler(tokens[type].text);
        if (sampler.empty()) return true;
        const size_t from = tokenizer.offsetOf(tokens[type]);
        const size_t to = tokenizer.offsetOf(tokens[name]);
        std::string replacement(sampler);
        // Blanks keep the columns; a line break inside the template arguments stays.
        for (size_t i = from + sampler.size(); i < to; ++i)
            replacement += text[i] == '\n' ? '\n' : ' ';
        text.replace(from, to - from, replacement);
        return true;
    });
    return text;
}

}  // namespace varc::frontend
