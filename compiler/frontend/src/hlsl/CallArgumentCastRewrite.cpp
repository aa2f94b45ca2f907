// SPDX-License-Identifier: Apache-2.0
// Casts the arguments of calls glslang found no overload for to their parameter types.
//
// FXC converts an argument to its parameter's numeric type implicitly (float4 -> float, with a
// warning); glslang finds no matching overload and stops. For a function of one signature this
// rewrite produces `f((float)(v))` from `f(v)` with `float f(float z)`, leaving out/inout, struct
// and resource parameters alone. It never adds, removes or moves a line break, so every `#line`
// mapping still holds.
#include <optional>

#include "HlslRewrite.h"
#include "HlslRewritePasses.h"

namespace varc::frontend::hlsl {

namespace {

using pruner::TokenKind;

class CallArgumentCastRewrite : public HlslRewrite {
public:
    explicit CallArgumentCastRewrite(RewriteState& state) : HlslRewrite(state) {}

    // Calls of |function| get each argument cast to its parameter's type: `f(v)` with
    // `float f(float z)` -> `f((float)(v))`, the implicit truncation (float4 -> float) the DirectX
    // compilers apply with a warning and glslang refuses. Only for a function of one signature,
    // and only parameters of a numeric type that are not `out` or `inout`.
    void run(std::string_view function) {
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

private:
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
};

}  // namespace

void castCallArguments(RewriteState& state, std::string_view function) {
    CallArgumentCastRewrite(state).run(function);
}

}  // namespace varc::frontend::hlsl
