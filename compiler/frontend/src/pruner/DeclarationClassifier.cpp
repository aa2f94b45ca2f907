// SPDX-License-Identifier: Apache-2.0
// Classifies one top-level declaration: kind, when it must be kept, names it defines and uses.
#include "pruner/DeclarationClassifier.h"

#include <algorithm>
#include <array>

#include "pruner/TokenMatch.h"

namespace varc::frontend::pruner {
namespace {

template <size_t N>
bool contains(const std::array<std::string_view, N>& words, std::string_view word) {
    return std::find(words.begin(), words.end(), word) != words.end();
}

// clang-format off
// Words that qualify a declaration and are never its declarator name (`layout(...) in;`).
constexpr std::array<std::string_view, 37> kQualifiers = {
    "in", "out", "inout", "uniform", "buffer", "shared", "const", "static", "extern",
    "attribute", "varying", "highp", "mediump", "lowp", "flat", "smooth", "noperspective",
    "centroid", "sample", "patch", "invariant", "precise", "coherent", "volatile", "restrict",
    "readonly", "writeonly", "groupshared", "row_major", "column_major", "nointerpolation",
    "linear", "snorm", "unorm", "globallycoherent", "layout", "inline"};

constexpr std::array<std::string_view, 8> kGlslStorage = {
    "uniform", "in", "out", "inout", "buffer", "shared", "attribute", "varying"};

// HLSL object types: glslang emits them only when used, and never into `$Global`.
constexpr std::array<std::string_view, 44> kHlslResourceTypes = {
    "texture", "texture1D", "texture2D", "texture3D", "textureCUBE", "sampler", "sampler1D",
    "sampler2D", "sampler3D", "samplerCUBE", "sampler_state", "SamplerState",
    "SamplerComparisonState", "Texture1D", "Texture1DArray", "Texture2D", "Texture2DArray",
    "Texture2DMS", "Texture2DMSArray", "Texture3D", "TextureCube", "TextureCubeArray",
    "RWTexture1D", "RWTexture1DArray", "RWTexture2D", "RWTexture2DArray", "RWTexture3D", "Buffer",
    "RWBuffer", "ByteAddressBuffer", "RWByteAddressBuffer", "StructuredBuffer",
    "RWStructuredBuffer", "AppendStructuredBuffer", "ConsumeStructuredBuffer", "ConstantBuffer",
    "TextureBuffer", "SubpassInput", "SubpassInputMS", "RasterizerOrderedBuffer",
    "RasterizerOrderedByteAddressBuffer", "RasterizerOrderedStructuredBuffer",
    "RasterizerOrderedTexture2D", "RaytracingAccelerationStructure"};
// clang-format on

void append(std::vector<std::string_view>& to, const std::vector<std::string_view>& from) {
    to.insert(to.end(), from.begin(), from.end());
}

}  // namespace

Declaration DeclarationClassifier::classify(const DeclarationSpan& span) const {
    Declaration decl;
    decl.begin = span.begin;
    decl.end = span.end;
    const size_t last = span.end - 1;  // the closing `;` or `}`
    const size_t first = skipAttributes(mTokens, span.begin, span.end);
    if (first >= last && isPunct(mTokens[last], ';')) {
        decl.kind = DeclarationKind::Empty;
        decl.retention = Retention::Never;
        return decl;
    }
    const Token& lead = mTokens[first];
    const bool braceBeforeAssign =
        span.firstBrace && (!span.firstAssign || *span.firstBrace < *span.firstAssign);
    const bool block = mDialect == ShaderDialect::Hlsl
                           ? isWord(lead, "cbuffer") || isWord(lead, "tbuffer")
                           : braceBeforeAssign;
    if (span.head && *span.head > first && !span.hasStruct) {
        classifyFunction(span, decl);
    } else if (span.hasStruct && span.firstBrace) {
        classifyStruct(span, first, decl);
    } else if (isWord(lead, "typedef")) {
        classifyTypedef(first, last, decl);
    } else if (block) {
        classifyBlock(span, first, decl);
    } else if (isWord(lead, "precision") || span.hasStruct || span.head || braceBeforeAssign) {
        collectReferences(mTokens, span.begin, span.end, decl.uses);  // Other, Always
    } else {
        classifyVariable(first, last, decl);
    }
    if (isWord(lead, "precision")) decl.kind = DeclarationKind::Precision;
    return decl;
}

void DeclarationClassifier::classifyFunction(const DeclarationSpan& span, Declaration& decl) const {
    decl.kind = DeclarationKind::Function;
    decl.retention = Retention::IfReachable;
    decl.hasBody = isPunct(mTokens[span.end - 1], '}');
    decl.defines.push_back(mTokens[*span.head].text);
    collectReferences(mTokens, span.begin, *span.head, decl.uses);
    collectReferences(mTokens, *span.head + 1, span.end, decl.uses);
}

// `[qualifiers] struct [S] { members } [declarators];`
void DeclarationClassifier::classifyStruct(const DeclarationSpan& span, size_t first,
                                           Declaration& decl) const {
    const size_t open = *span.firstBrace;
    const size_t close = findClosingBracket(mTokens, open).value_or(open);
    Statement head;
    size_t keyword = first;
    for (; keyword < open && !isWord(mTokens[keyword], "struct"); ++keyword) {
        noteQualifier(mTokens[keyword].text, head);
    }
    const bool isTypedef = isWord(mTokens[first], "typedef");
    if (keyword + 1 < open && mTokens[keyword + 1].kind == TokenKind::Identifier) {
        decl.defines.push_back(mTokens[keyword + 1].text);
    }
    addMembers(open, close, /*membersAreGlobal=*/false, decl);
    Statement tail = analyzeStatement(close + 1, span.end - 1, /*typeGiven=*/true);
    append(decl.uses, tail.uses);
    append(decl.defines, tail.names);
    if (tail.names.empty() || isTypedef) {
        decl.kind = isTypedef ? DeclarationKind::Typedef : DeclarationKind::Struct;
        decl.retention = decl.defines.empty() ? Retention::Always : Retention::IfReachable;
        return;
    }
    tail.isStatic = head.isStatic;  // `static struct {...} s;` and friends
    tail.isConst = head.isConst;
    tail.isGroupShared = head.isGroupShared;
    tail.hasStorage = head.hasStorage;
    tail.type = "struct";
    decl.kind = DeclarationKind::Variable;
    decl.retention = variableRetention(tail);
}

// HLSL `cbuffer B : register(b0) { members }` or GLSL `layout(...) uniform B { members } [inst];`
void DeclarationClassifier::classifyBlock(const DeclarationSpan& span, size_t first,
                                          Declaration& decl) const {
    decl.kind = DeclarationKind::Block;
    const size_t open = *span.firstBrace;
    const size_t close = findClosingBracket(mTokens, open).value_or(open);
    if (mDialect == ShaderDialect::Hlsl) {
        decl.retention = Retention::IfReachable;
        if (mTokens[first + 1].kind == TokenKind::Identifier) {
            decl.defines.push_back(mTokens[first + 1].text);
        }
        addMembers(open, close, /*membersAreGlobal=*/true, decl);
        return;
    }
    decl.retention = Retention::Always;  // glslang emits unused GLSL blocks
    if (mTokens[open - 1].kind == TokenKind::Identifier) {
        decl.defines.push_back(mTokens[open - 1].text);
    }
    collectReferences(mTokens, first, open - 1, decl.uses);
    const size_t last = isPunct(mTokens[span.end - 1], ';') ? span.end - 1 : span.end;
    const Statement tail = analyzeStatement(close + 1, last, /*typeGiven=*/true);
    append(decl.defines, tail.names);
    append(decl.uses, tail.uses);
    addMembers(open, close, /*membersAreGlobal=*/tail.names.empty(), decl);
}

void DeclarationClassifier::classifyVariable(size_t first, size_t last, Declaration& decl) const {
    const Statement statement = analyzeStatement(first, last, /*typeGiven=*/false);
    decl.kind = DeclarationKind::Variable;
    decl.retention = variableRetention(statement);
    decl.defines = statement.names;
    decl.uses = statement.uses;
}

void DeclarationClassifier::classifyTypedef(size_t first, size_t last, Declaration& decl) const {
    const Statement statement = analyzeStatement(first + 1, last, /*typeGiven=*/false);
    decl.kind = DeclarationKind::Typedef;
    decl.retention = statement.names.empty() ? Retention::Always : Retention::IfReachable;
    decl.defines = statement.names;
    decl.uses = statement.uses;
}

// Walks `qualifiers type<args> name[N] : SEMANTIC = init, name2 ...` in [|begin|, |end|).
// Identifiers after a depth-0 `:` (semantics, `register(...)`, `packoffset(...)`) are skipped,
// template arguments and initializers are uses, declarator names are collected.
DeclarationClassifier::Statement DeclarationClassifier::analyzeStatement(size_t begin, size_t end,
                                                                         bool typeGiven) const {
    Statement statement;
    int depth = 0;
    int angles = 0;
    bool inInitializer = false;
    bool inSemantic = false;
    for (size_t i = begin; i < end; ++i) {
        const Token& token = mTokens[i];
        const bool top = depth == 0 && !inInitializer;
        if (isOpenBracket(token) || isCloseBracket(token)) {
            depth += isOpenBracket(token) ? 1 : -1;
        } else if (depth == 0 && (isPunct(token, '=') || (isPunct(token, ',') && angles == 0))) {
            inInitializer = isPunct(token, '=');
            inSemantic = false;
        } else if (top && isPunct(token, ':')) {
            inSemantic = true;
        } else if (top && (isPunct(token, '<') || isPunct(token, '>'))) {
            angles = std::max(0, angles + (isPunct(token, '<') ? 1 : -1));
        } else if (token.kind == TokenKind::Identifier && !inSemantic &&
                   !(i > begin && isPunct(mTokens[i - 1], '.'))) {
            if (top && angles == 0 && isDeclaratorName(i, begin, end, typeGiven)) {
                statement.names.push_back(token.text);
                continue;
            }
            const bool beforeNames = top && angles == 0 && statement.names.empty();
            if (beforeNames && !noteQualifier(token.text, statement) && statement.type.empty()) {
                statement.type = token.text;
            }
            statement.uses.push_back(token.text);
        }
    }
    return statement;
}

bool DeclarationClassifier::isDeclaratorName(size_t index, size_t begin, size_t end,
                                             bool typeGiven) const {
    if (index == begin && !typeGiven) return false;
    if (contains(kQualifiers, mTokens[index].text)) return false;
    if (index + 1 >= end) return true;
    const Token& next = mTokens[index + 1];
    return isPunct(next, ',') || isPunct(next, '=') || isPunct(next, '[') || isPunct(next, ':');
}

// Member declarations between |open| and |close| (a `{...}` body), split at depth-0 `;`.
void DeclarationClassifier::addMembers(size_t open, size_t close, bool membersAreGlobal,
                                       Declaration& decl) const {
    int depth = 0;
    size_t statementBegin = open + 1;
    for (size_t i = open + 1; i <= close; ++i) {
        const Token& token = mTokens[i];
        const bool ends = i == close || (depth == 0 && isPunct(token, ';'));
        if (isOpenBracket(token)) ++depth;
        if (isCloseBracket(token)) --depth;
        if (!ends) continue;
        if (statementBegin < i) {
            const Statement member = analyzeStatement(statementBegin, i, /*typeGiven=*/false);
            append(decl.uses, member.uses);
            if (membersAreGlobal) append(decl.defines, member.names);
        }
        statementBegin = i + 1;
    }
}

Retention DeclarationClassifier::variableRetention(const Statement& statement) const {
    if (statement.names.empty()) return Retention::Always;  // e.g. `layout(...) in;`
    if (mDialect == ShaderDialect::Glsl) {
        return statement.isConst && !statement.hasStorage ? Retention::IfReachable
                                                          : Retention::Always;
    }
    if (statement.isStatic || statement.isConst || statement.isGroupShared ||
        contains(kHlslResourceTypes, statement.type)) {
        return Retention::IfReachable;
    }
    return Retention::GlobalGroup;
}

bool DeclarationClassifier::noteQualifier(std::string_view word, Statement& statement) {
    if (!contains(kQualifiers, word)) return false;
    statement.isStatic = statement.isStatic || word == "static";
    statement.isConst = statement.isConst || word == "const";
    statement.isGroupShared = statement.isGroupShared || word == "groupshared";
    statement.hasStorage = statement.hasStorage || contains(kGlslStorage, word);
    return true;
}

}  // namespace varc::frontend::pruner
