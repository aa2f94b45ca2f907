// SPDX-License-Identifier: Apache-2.0
// Source rewrites that let glslang's HLSL front end accept what Unity's HLSL compilers accept.
#include "varc/frontend/HlslRewrites.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>
#include <set>
#include <vector>

#include "pruner/ShaderTokenizer.h"
#include "varc/core/AsciiIdentifier.h"

namespace varc::frontend {

namespace {

using pruner::Token;
using pruner::TokenKind;

// Text inserted at an offset of the original text; applied from the back.
struct Insertion {
    size_t offset = 0;
    std::string text;
    bool operator<(const Insertion& other) const { return offset < other.offset; }
};

struct Replacement {
    size_t offset = 0, length = 0;
    std::string text;
};

bool isPunct(const Token& token, char c) {
    return token.kind == TokenKind::Punct && token.text.size() == 1 && token.text[0] == c;
}

// The literal at the start of |text| ("0x1376312589U + 1" -> "0x1376312589U"), or "".
std::string_view hexLiteralAt(std::string_view text) {
    if (text.size() < 3 || text[0] != '0' || (text[1] != 'x' && text[1] != 'X')) return {};
    size_t end = 2;
    while (end < text.size() && isAsciiIdentifierChar(text[end])) ++end;
    return text.substr(0, end);
}

// The DirectX compilers keep the low 32 bits of a hexadecimal literal too wide for its type
// (with a warning); glslang stops. "0x1376312589U" -> "0x76312589U"; nullopt when |literal|
// is not a hexadecimal literal of more than 32 significant bits.
std::optional<std::string> truncatedHexLiteral(std::string_view literal) {
    if (hexLiteralAt(literal).size() != literal.size()) return std::nullopt;
    size_t digitsEnd = 2;
    while (digitsEnd < literal.size() &&
           std::isxdigit(static_cast<unsigned char>(literal[digitsEnd]))) {
        ++digitsEnd;
    }
    std::string_view digits = literal.substr(2, digitsEnd - 2);
    while (digits.size() > 1 && digits.front() == '0') digits.remove_prefix(1);
    if (digits.size() <= 8) return std::nullopt;
    return std::string(literal.substr(0, 2)) + std::string(digits.substr(digits.size() - 8)) +
           std::string(literal.substr(digitsEnd));
}

class Rewriter {
public:
    explicit Rewriter(const pruner::ShaderTokenizer& tokens)
        : mTokenizer(tokens), mTokens(tokens.tokens()) {}

    std::string rewrite(std::string_view text, const std::vector<std::string>& unmatchedCalls) {
        markDeclarationBodies();
        for (const std::string& function : unmatchedCalls) castCallArguments(function);
        castSwitchConditions();
        copyWrittenUniforms();
        spellOutMatrixSwizzles();
        truncateWideHexLiterals();
        dropEmptyMemberDeclarations();
        splitSelfInitializations();
        hoistCbufferResources();
        return apply(text);
    }

    // Only the front-face parameters (see fixFrontFaceParameterTypes).
    std::string rewriteFrontFaceTypes(std::string_view text) {
        makeFrontFaceParametersBool();
        replaceFaceParameters();
        return apply(text);
    }

private:
    std::string apply(std::string_view text) {
        if (mInsertions.empty() && mReplacements.empty()) return std::string(text);
        for (const Insertion& insertion : mInsertions) {
            mReplacements.push_back({insertion.offset, 0, insertion.text});
        }
        std::stable_sort(mReplacements.begin(), mReplacements.end(),
                         [](const Replacement& a, const Replacement& b) { return a.offset > b.offset; });
        std::string result(text);
        for (const Replacement& r : mReplacements) result.replace(r.offset, r.length, r.text);
        return result;
    }

    size_t offsetOf(size_t i) const { return mTokenizer.offsetOf(mTokens[i]); }
    size_t endOf(size_t i) const { return offsetOf(i) + mTokens[i].text.size(); }
    bool adjacent(size_t a, size_t b) const { return endOf(a) == offsetOf(b); }
    bool is(size_t i, char c) const { return i < mTokens.size() && isPunct(mTokens[i], c); }
    bool isWord(size_t i, std::string_view word) const {
        return i < mTokens.size() && mTokens[i].kind == TokenKind::Identifier &&
               mTokens[i].text == word;
    }

    // The index of the token closing the bracket opened at |open|, or npos.
    size_t matching(size_t open) const {
        char opener = mTokens[open].text[0];
        char closer = opener == '(' ? ')' : opener == '[' ? ']' : '}';
        int depth = 0;
        for (size_t i = open; i < mTokens.size(); ++i) {
            if (is(i, opener)) ++depth;
            if (is(i, closer) && --depth == 0) return i;
        }
        return std::string::npos;
    }

    // Brace depth of every token, and whether it lies in a struct or cbuffer body, where names
    // are members rather than uses.
    void markDeclarationBodies() {
        mDepth.assign(mTokens.size(), 0);
        mInDeclarationBody.assign(mTokens.size(), false);
        std::vector<bool> bodyStack;
        bool pendingBody = false, pendingCbuffer = false;
        size_t cbufferOpen = std::string::npos;
        int depth = 0;
        for (size_t i = 0; i < mTokens.size(); ++i) {
            if (isWord(i, "struct") || isWord(i, "cbuffer") || isWord(i, "tbuffer")) {
                pendingBody = true;
                pendingCbuffer = isWord(i, "cbuffer") && depth == 0;
            }
            if (is(i, ';') || is(i, '(')) pendingBody = pendingCbuffer = false;
            if (is(i, '{')) {
                bodyStack.push_back(pendingBody || (!bodyStack.empty() && bodyStack.back()));
                if (pendingCbuffer) cbufferOpen = i;
                pendingBody = pendingCbuffer = false;
                ++depth;
            }
            mDepth[i] = depth;
            mInDeclarationBody[i] = !bodyStack.empty() && bodyStack.back();
            if (is(i, '}') && depth > 0) {
                if (depth == 1 && cbufferOpen != std::string::npos) {
                    mCbufferBodies.push_back({cbufferOpen, i});
                    cbufferOpen = std::string::npos;
                }
                --depth;
                bodyStack.pop_back();
            }
        }
    }

    void castSwitchConditions() {
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

    // `M._m20_m21_m22` -> `float3(M[2][0], M[2][1], M[2][2])` and `M._11_22` ->
    // `float2(M[0][0], M[1][1])` (zero- and one-based element names; row, then column), for a
    // matrix named by one identifier. Single elements (`M._m03`) glslang reads itself.
    void spellOutMatrixSwizzles() {
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
            mReplacements.push_back({offsetOf(i - 2), endOf(i) - offsetOf(i - 2), text + ")"});
        }
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

    // `0x1376312589U` -> `0x76312589U` (see truncatedHexLiteral).
    void truncateWideHexLiterals() {
        for (size_t i = 0; i < mTokens.size(); ++i) {
            if (mTokens[i].kind != TokenKind::Number) continue;
            if (auto kept = truncatedHexLiteral(mTokens[i].text)) {
                mReplacements.push_back({offsetOf(i), mTokens[i].text.size(), *kept});
            }
        }
    }

    // Declaration macros that expand to nothing leave empty declarations (`float a;;`, `{ ;`)
    // in structs, cbuffers and at file scope, which the DirectX compilers skip and glslang
    // refuses. (A `;` after a file-scope `}` ends a struct or cbuffer and stays.)
    void dropEmptyMemberDeclarations() {
        for (size_t i = 1; i < mTokens.size(); ++i) {
            if (!is(i, ';')) continue;
            bool inBody = mInDeclarationBody[i] && mDepth[i] > 0;
            bool empty = inBody ? (is(i - 1, ';') || is(i - 1, '{'))
                                : (mDepth[i] == 0 && is(i - 1, ';'));
            if (empty) mReplacements.push_back({offsetOf(i), 1, " "});
        }
    }

    // `cbuffer M { sampler2D _A; float4 _S; };` -> `sampler2D _A; cbuffer M { float4 _S; };`
    // (the moved text blanked in the body, its line breaks kept): the DirectX compilers take a
    // resource declared in a cbuffer as a global, glslang makes it a member, which Vulkan forbids.
    void hoistCbufferResources() {
        for (const auto& [open, close] : mCbufferBodies) {
            size_t keyword = open;
            while (keyword > 0 && !isWord(keyword, "cbuffer") && !isWord(keyword, "tbuffer")) {
                --keyword;
            }
            std::string hoistedAll;
            size_t begin = open + 1;
            for (size_t i = open + 1; i < close; ++i) {
                if (!is(i, ';') || mDepth[i] != 1) continue;
                if (isResourceDeclaration(begin, i)) {
                    std::string declaration =
                        mTokenizer.code().substr(offsetOf(begin), endOf(i) - offsetOf(begin));
                    std::string hoisted(declaration), blank(declaration);
                    for (size_t c = 0; c < declaration.size(); ++c) {
                        bool lineBreak = declaration[c] == '\n' || declaration[c] == '\r';
                        if (lineBreak) hoisted[c] = ' ';
                        if (!lineBreak) blank[c] = ' ';
                    }
                    hoistedAll += hoisted + " ";
                    mReplacements.push_back({offsetOf(begin), declaration.size(), blank});
                }
                begin = i + 1;
            }
            if (!hoistedAll.empty()) mInsertions.push_back({offsetOf(keyword), hoistedAll});
        }
    }

    // Whether the statement [begin, end) declares a texture, sampler or buffer.
    bool isResourceDeclaration(size_t begin, size_t end) const {
        size_t type = isWord(begin, "uniform") ? begin + 1 : begin;
        if (type >= end || mTokens[type].kind != TokenKind::Identifier) return false;
        std::string_view name = mTokens[type].text;
        return name.rfind("sampler", 0) == 0 || name.rfind("Texture", 0) == 0 ||
               name.rfind("SamplerState", 0) == 0 || name.rfind("SamplerComparisonState", 0) == 0 ||
               name.find("Buffer") != std::string_view::npos;
    }

    // Calls of |function| get each argument cast to its parameter's type: `f(v)` with
    // `float f(float z)` -> `f((float)(v))`, the implicit truncation (float4 -> float) the DirectX
    // compilers apply with a warning and glslang refuses. Only for a function of one signature,
    // and only parameters of a numeric type that are not `out` or `inout`.
    void castCallArguments(std::string_view function) {
        std::optional<std::vector<std::string>> casts;
        for (size_t i = 1; i + 1 < mTokens.size(); ++i) {
            if (!isWord(i, function) || !is(i + 1, '(') || mDepth[i] != 0 ||
                mTokens[i - 1].kind != TokenKind::Identifier) {
                continue;
            }
            std::vector<std::string> these = parameterCasts(i + 1);
            if (casts && *casts != these) return;  // overloads: leave every call alone
            casts = std::move(these);
        }
        if (!casts) return;
        for (size_t i = 1; i + 1 < mTokens.size(); ++i) {
            if (!isWord(i, function) || !is(i + 1, '(') || mDepth[i] == 0 || is(i - 1, '.')) {
                continue;
            }
            std::vector<std::pair<size_t, size_t>> arguments = argumentsOf(i + 1);
            if (arguments.size() != casts->size()) continue;
            for (size_t a = 0; a < arguments.size(); ++a) {
                if ((*casts)[a].empty()) continue;
                mInsertions.push_back({offsetOf(arguments[a].first), "(" + (*casts)[a] + ")("});
                mInsertions.push_back({endOf(arguments[a].second), ")"});
            }
        }
    }

    // The first and last token of each argument in the parentheses opened at |open|.
    std::vector<std::pair<size_t, size_t>> argumentsOf(size_t open) const {
        std::vector<std::pair<size_t, size_t>> arguments;
        size_t close = matching(open);
        if (close == std::string::npos || close == open + 1) return arguments;
        size_t begin = open + 1;
        int depth = 0;
        for (size_t j = open + 1; j <= close; ++j) {
            if (is(j, '(') || is(j, '[') || is(j, '{')) ++depth;
            if (is(j, ')') || is(j, ']') || is(j, '}')) --depth;
            if ((depth == 0 && is(j, ',')) || j == close) {
                if (j == begin) return {};
                arguments.emplace_back(begin, j - 1);
                begin = j + 1;
            }
        }
        return arguments;
    }

    // Per parameter of the declaration whose list opens at |open|: the numeric type to cast an
    // argument to, or "" (out/inout, structs, resources, anything unusual).
    std::vector<std::string> parameterCasts(size_t open) const {
        std::vector<std::string> casts;
        for (const auto& [first, last] : argumentsOf(open)) {
            size_t type = first;
            while (type < last && (isWord(type, "in") || isWord(type, "const") ||
                                   isWord(type, "uniform") || isWord(type, "precise"))) {
                ++type;
            }
            bool byValue = !isWord(type, "out") && !isWord(type, "inout");
            bool named = type + 1 <= last && mTokens[type + 1].kind == TokenKind::Identifier;
            casts.push_back(byValue && named && isNumericType(mTokens[type].text)
                                ? std::string(mTokens[type].text)
                                : "");
        }
        return casts;
    }

    // "float", "half3", "int2x2", ... (scalar, vector and matrix types of the numeric bases).
    static bool isNumericType(std::string_view name) {
        for (std::string_view base :
             {"float", "half", "int", "uint", "bool", "double", "min16float"}) {
            if (name.rfind(base, 0) != 0) continue;
            std::string_view shape = name.substr(base.size());
            bool vector = shape.size() == 1 && shape[0] >= '1' && shape[0] <= '4';
            bool matrix = shape.size() == 3 && shape[0] >= '1' && shape[0] <= '4' &&
                          shape[1] == 'x' && shape[2] >= '1' && shape[2] <= '4';
            if (shape.empty() || vector || matrix) return true;
        }
        return false;
    }

    // `T o = f(o);` in a function body -> `T o; o = f(o);`: HLSL puts a local in scope in its
    // own initializer (uninitialised, fxc warns), glslang does not. Only a declaration that
    // starts a statement, of one identifier type and one declarator, whose initializer names the
    // variable; `const` and `static` declarations (which need their initializer) are left alone.
    void splitSelfInitializations() {
        static const std::set<std::string_view> kNotType = {"return", "else", "do", "case",
                                                             "const", "static", "goto"};
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

    // `uint facing : SV_IsFrontFace` -> `bool facing : SV_IsFrontFace`: Vulkan's FrontFacing is a
    // bool, and glslang passes any other type through into invalid SPIR-V.
    void makeFrontFaceParametersBool() {
        for (size_t i = 3; i < mTokens.size(); ++i) {
            if (mTokens[i].text != "SV_IsFrontFace" || !is(i - 1, ':')) continue;
            size_t type = i - 3;
            if (mTokens[type].kind != TokenKind::Identifier || mTokens[type].text == "bool") continue;
            mReplacements.push_back({offsetOf(type), mTokens[type].text.size(), "bool"});
        }
    }

    // `float4 f(v2f i, half facing : VFACE) : SV_Target { ... }` ->
    // `float4 f(v2f i, bool facing_varcFrontFace : SV_IsFrontFace) : SV_Target { half facing =
    // facing_varcFrontFace ? 1 : -1; ... }`: the Direct3D 9 face register is a float, positive
    // on front faces and negative on back faces; glslang takes VFACE for an interpolator.
    void replaceFaceParameters() {
        for (size_t i = 3; i < mTokens.size(); ++i) {
            if (!isWord(i, "VFACE") || !is(i - 1, ':')) continue;
            size_t name = i - 2, type = i - 3;
            if (mTokens[name].kind != TokenKind::Identifier ||
                mTokens[type].kind != TokenKind::Identifier) {
                continue;
            }
            std::string bound = std::string(mTokens[name].text) + "_varcFrontFace";
            mReplacements.push_back({offsetOf(type), endOf(i) - offsetOf(type),
                                     "bool " + bound + " : SV_IsFrontFace"});
            size_t body = functionBodyAfterParameter(i);
            if (body == std::string::npos) continue;
            mInsertions.push_back({endOf(body), " " + std::string(mTokens[type].text) + " " +
                                                    std::string(mTokens[name].text) + " = " +
                                                    bound + " ? 1 : -1;"});
        }
    }

    // The '{' opening the body of the function whose parameter list holds token |i|, or npos
    // (a prototype, or not a parameter at all).
    size_t functionBodyAfterParameter(size_t i) const {
        int depth = 0;
        size_t j = i;
        for (; j < mTokens.size(); ++j) {
            if (is(j, '(')) ++depth;
            if (is(j, ')') && --depth < 0) break;
            if (depth == 0 && (is(j, ';') || is(j, '{'))) return std::string::npos;
        }
        for (++j; j < mTokens.size(); ++j) {
            if (is(j, '{')) return j;
            if (is(j, ';') || is(j, '(') || is(j, '}')) return std::string::npos;
        }
        return std::string::npos;
    }

    bool hasUnsignedCase(size_t begin, size_t end) const {
        for (size_t i = begin; i + 1 < end; ++i) {
            if (!isWord(i, "case") || mTokens[i + 1].kind != TokenKind::Number) continue;
            char last = mTokens[i + 1].text.back();
            if (last == 'u' || last == 'U') return true;
        }
        return false;
    }

    // A ';' at file scope, or a brace opening or closing a file-scope body (mDepth counts the
    // brace itself as inside).
    bool endsTopLevelStatement(size_t i) const {
        return (is(i, ';') && mDepth[i] == 0) || ((is(i, '{') || is(i, '}')) && mDepth[i] == 1);
    }

    // A uniform declarator: `[uniform] Type name {, name};` at file scope or in a cbuffer.
    struct Declarator {
        size_t nameToken = 0;
        size_t statementBegin = 0, statementEnd = 0;  // first token and the ';'
        size_t copyAfter = 0;  // the token after which the copy is declared
        std::string type;
    };

    std::vector<Declarator> looseUniforms() const {
        static const std::set<std::string_view> kNotUniform = {
            "static", "const",   "struct",   "typedef", "cbuffer", "tbuffer", "groupshared",
            "extern", "return",  "namespace", "class",  "interface", "in", "out", "inout"};
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
        std::string type(mTokenizer.code().substr(offsetOf(typeBegin),
                                                  endOf(first - 1) - offsetOf(typeBegin)));
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

    // Whether the use of a name at |i| writes it: `x = `, `x op= `, `x.yz = `, `x[i] = `,
    // `x++`, `++x`.
    bool isWrite(size_t i) const {
        if (i >= 2 && (is(i - 1, '+') || is(i - 1, '-')) && is(i - 2, mTokens[i - 1].text[0]) &&
            adjacent(i - 2, i - 1)) {
            return true;
        }
        size_t j = i + 1;
        while (j < mTokens.size()) {
            if (is(j, '.') && j + 1 < mTokens.size() &&
                mTokens[j + 1].kind == TokenKind::Identifier) {
                j += 2;
            } else if (is(j, '[')) {
                size_t close = matching(j);
                if (close == std::string::npos) return false;
                j = close + 1;
            } else {
                break;
            }
        }
        if (j >= mTokens.size() || mTokens[j].kind != TokenKind::Punct) return false;
        char c = mTokens[j].text[0];
        bool next = j + 1 < mTokens.size() && adjacent(j, j + 1);
        if (c == '=') return !(next && is(j + 1, '='));
        if ((c == '+' || c == '-') && next && is(j + 1, c)) return true;
        if (std::string_view("+-*/%&|^").find(c) != std::string_view::npos) {
            return next && is(j + 1, '=');
        }
        if ((c == '<' || c == '>') && next && is(j + 1, c)) {
            return j + 2 < mTokens.size() && adjacent(j + 1, j + 2) && is(j + 2, '=');
        }
        return false;
    }

    bool isUse(size_t i, std::string_view name) const {
        return mTokens[i].kind == TokenKind::Identifier && mTokens[i].text == name &&
               !mInDeclarationBody[i] && !(i > 0 && is(i - 1, '.'));
    }

    void copyWrittenUniforms() {
        for (const Declarator& uniform : looseUniforms()) {
            std::string_view name = mTokens[uniform.nameToken].text;
            bool written = false;
            for (size_t i = 0; i < mTokens.size() && !written; ++i) {
                written = mDepth[i] > 0 && isUse(i, name) && isWrite(i);
            }
            if (!written) continue;
            std::string copy = std::string(name) + "_varcCopy";
            mInsertions.push_back({endOf(uniform.copyAfter), " static " + uniform.type + " " +
                                                                   copy + " = " +
                                                                   std::string(name) + ";"});
            for (size_t i = 0; i < mTokens.size(); ++i) {
                if (i >= uniform.statementBegin && i <= uniform.statementEnd) continue;
                if (isUse(i, name)) mReplacements.push_back({offsetOf(i), name.size(), copy});
            }
        }
    }

    const pruner::ShaderTokenizer& mTokenizer;
    const std::vector<Token>& mTokens;
    std::vector<int> mDepth;
    std::vector<bool> mInDeclarationBody;
    std::vector<std::pair<size_t, size_t>> mCbufferBodies;  // file-scope cbuffer '{' and '}'

    std::vector<Insertion> mInsertions;
    std::vector<Replacement> mReplacements;
};

}  // namespace

std::string rewriteHlslForGlslang(std::string_view text,
                                  const std::vector<std::string>& unmatchedCalls) {
    pruner::ShaderTokenizer tokenizer;
    if (!tokenizer.tokenize(text)) return std::string(text);
    return Rewriter(tokenizer).rewrite(text, unmatchedCalls);
}

std::string truncateWideHexLiterals(std::string_view text) {
    std::string result;
    result.reserve(text.size());
    size_t i = 0;
    while (i < text.size()) {
        std::string_view literal =
            (i == 0 || !isAsciiIdentifierChar(text[i - 1])) ? hexLiteralAt(text.substr(i)) : "";
        if (literal.empty()) {
            result += text[i++];
            continue;
        }
        std::optional<std::string> kept = truncatedHexLiteral(literal);
        result += kept ? *kept : std::string(literal);
        i += literal.size();
    }
    return result;
}

std::string fixFrontFaceParameterTypes(std::string_view text) {
    if (text.find("SV_IsFrontFace") == std::string_view::npos &&
        text.find("VFACE") == std::string_view::npos) {
        return std::string(text);
    }
    pruner::ShaderTokenizer tokenizer;
    if (!tokenizer.tokenize(text)) return std::string(text);
    return Rewriter(tokenizer).rewriteFrontFaceTypes(text);
}

}  // namespace varc::frontend
