// SPDX-License-Identifier: Apache-2.0
// Macro expansion and integer evaluation of one `#if` expression.
#include "ConditionEvaluator.h"

#include <algorithm>
#include <cstdlib>
#include <span>
#include <string>

namespace varc::driver::projection {

namespace {

constexpr int kMaxDepth = 64;
constexpr long long kLimit = 1LL << 32;

// Expands macros in a token list (C's rescanning, with the names being expanded hidden).
class Expander {
public:
    explicit Expander(MacroScope& scope) : mScope(scope) {}
    bool failed() const { return mFailed; }

    void expand(std::span<const std::string_view> in, std::vector<std::string_view>& out) {
        if (++mDepth > kMaxDepth) mFailed = true;
        for (size_t i = 0; i < in.size() && !mFailed; ++i) {
            std::string_view token = in[i];
            if (token == "defined") {
                i = expandDefined(in, i, out);
            } else if (!isIdentifierToken(token) ||
                       std::find(mHidden.begin(), mHidden.end(), token) != mHidden.end()) {
                out.push_back(token);
            } else if (const PpLine* macro = mScope.macro(token); !macro) {
                out.push_back(token);
            } else if (!macro->functionLike) {
                expandBody(token, macro->tokens, out);
                // A function-like macro named last by the body, called by what follows.
                if (i + 1 < in.size() && in[i + 1] == "(" && !out.empty() &&
                    isIdentifierToken(out.back())) {
                    const PpLine* last = mScope.macro(out.back());
                    if (last && last->functionLike) mFailed = true;
                }
            } else if (i + 1 < in.size() && in[i + 1] == "(") {
                i = expandCall(in, i, *macro, out);
            } else {
                out.push_back(token);
            }
        }
        --mDepth;
    }

private:
    size_t expandDefined(std::span<const std::string_view> in, size_t i,
                         std::vector<std::string_view>& out) {
        size_t j = i + 1;
        bool paren = j < in.size() && in[j] == "(";
        if (paren) ++j;
        if (j >= in.size() || !isIdentifierToken(in[j])) {
            mFailed = true;
            return j;
        }
        out.push_back(mScope.macro(in[j]) ? "1" : "0");
        if (paren && (j + 1 >= in.size() || in[j + 1] != ")")) mFailed = true;
        return paren ? j + 1 : j;
    }

    void expandBody(std::string_view name, std::span<const std::string_view> body,
                    std::vector<std::string_view>& out) {
        if (std::find(body.begin(), body.end(), "##") != body.end()) {
            mFailed = true;
            return;
        }
        mHidden.push_back(name);
        expand(body, out);
        mHidden.pop_back();
    }

    // |in[i]| names function-like |macro| and |in[i + 1]| is "(": returns the index of ")".
    size_t expandCall(std::span<const std::string_view> in, size_t i, const PpLine& macro,
                      std::vector<std::string_view>& out) {
        std::vector<std::vector<std::string_view>> args(1);
        size_t j = i + 2;
        for (int level = 0; j < in.size(); ++j) {
            if (in[j] == ")" && level == 0) break;
            if (in[j] == "(") ++level;
            if (in[j] == ")") --level;
            if (in[j] == "," && level == 0) {
                args.emplace_back();
            } else {
                args.back().push_back(in[j]);
            }
        }
        bool noArguments = macro.params.empty() && args.size() == 1 && args[0].empty();
        if (j >= in.size() || (!noArguments && args.size() != macro.params.size())) {
            mFailed = true;
            return j;
        }
        std::vector<std::string_view> substituted;
        for (std::string_view token : macro.tokens) {
            if (token == "#" || token == "##") mFailed = true;
            auto param = std::find(macro.params.begin(), macro.params.end(), token);
            if (param == macro.params.end()) {
                substituted.push_back(token);
            } else {
                expand(args[static_cast<size_t>(param - macro.params.begin())], substituted);
            }
        }
        if (!mFailed) expandBody(in[i], substituted, out);
        return j;
    }

    MacroScope& mScope;
    std::vector<std::string_view> mHidden;
    int mDepth = 0;
    bool mFailed = false;
};

std::optional<long long> numberOf(std::string_view token) {
    while (!token.empty() && std::string_view("uUlL").find(token.back()) != std::string_view::npos)
        token.remove_suffix(1);
    std::string text(token);
    char* end = nullptr;
    long long value = std::strtoll(text.c_str(), &end, 0);
    if (text.empty() || end != text.c_str() + text.size()) return std::nullopt;
    return value;
}

int precedenceOf(std::string_view op) {
    static constexpr std::pair<std::string_view, int> kTable[] = {
        {"||", 1}, {"&&", 2}, {"|", 3}, {"^", 4},  {"&", 5},  {"==", 6},
        {"!=", 6}, {"<", 7},  {">", 7}, {"<=", 7}, {">=", 7}, {"<<", 8},
        {">>", 8}, {"+", 9},  {"-", 9}, {"*", 10}, {"/", 10}, {"%", 10}};
    for (const auto& [name, precedence] : kTable)
        if (name == op) return precedence;
    return -1;
}

// Recursive descent over the expanded tokens; any surprise ends in nullopt.
class Evaluator {
public:
    explicit Evaluator(const std::vector<std::string_view>& tokens) : mTokens(tokens) {}

    std::optional<long long> run() {
        std::optional<long long> value = ternary();
        if (mPos != mTokens.size()) return std::nullopt;
        return value;
    }

private:
    std::string_view peek() const { return mPos < mTokens.size() ? mTokens[mPos] : ""; }

    std::optional<long long> ternary() {
        std::optional<long long> condition = binary(1);
        if (!condition || peek() != "?") return condition;
        ++mPos;
        std::optional<long long> a = ternary();
        if (!a || peek() != ":") return std::nullopt;
        ++mPos;
        std::optional<long long> b = ternary();
        if (!b) return std::nullopt;
        return *condition ? a : b;
    }

    std::optional<long long> binary(int minPrecedence) {
        std::optional<long long> lhs = unary();
        while (lhs) {
            std::string_view op = peek();
            int precedence = precedenceOf(op);
            if (precedence < minPrecedence) break;
            ++mPos;
            std::optional<long long> rhs = binary(precedence + 1);
            if (!rhs) return std::nullopt;
            lhs = apply(op, *lhs, *rhs);
            if (lhs && (*lhs >= kLimit || *lhs <= -kLimit)) return std::nullopt;
        }
        return lhs;
    }

    static std::optional<long long> apply(std::string_view op, long long a, long long b) {
        if ((op == "/" || op == "%") && b == 0) return std::nullopt;
        if ((op == "<<" || op == ">>") && (b < 0 || b > 31)) return std::nullopt;
        if (op == "||") return (a || b) ? 1 : 0;
        if (op == "&&") return (a && b) ? 1 : 0;
        if (op == "|") return a | b;
        if (op == "^") return a ^ b;
        if (op == "&") return a & b;
        if (op == "==") return a == b ? 1 : 0;
        if (op == "!=") return a != b ? 1 : 0;
        if (op == "<") return a < b ? 1 : 0;
        if (op == ">") return a > b ? 1 : 0;
        if (op == "<=") return a <= b ? 1 : 0;
        if (op == ">=") return a >= b ? 1 : 0;
        if (op == "<<") return a << b;
        if (op == ">>") return a >> b;
        if (op == "+") return a + b;
        if (op == "-") return a - b;
        if (op == "*") return a * b;
        if (op == "/") return a / b;
        return a % b;
    }

    std::optional<long long> unary() {
        std::string_view token = peek();
        if (token.empty()) return std::nullopt;
        ++mPos;
        if (token == "!" || token == "~" || token == "-" || token == "+") {
            std::optional<long long> value = unary();
            if (!value) return std::nullopt;
            if (token == "!") return *value ? 0 : 1;
            if (token == "~") return ~*value;
            return token == "-" ? -*value : *value;
        }
        if (token == "(") {
            std::optional<long long> value = ternary();
            if (!value || peek() != ")") return std::nullopt;
            ++mPos;
            return value;
        }
        if (token[0] >= '0' && token[0] <= '9') return numberOf(token);
        // A name no macro defines is 0; `true` and `false` are left to glslang.
        if (isIdentifierToken(token) && token != "true" && token != "false") return 0;
        return std::nullopt;
    }

    const std::vector<std::string_view>& mTokens;
    size_t mPos = 0;
};

}  // namespace

std::optional<long long> evaluateCondition(const std::vector<std::string_view>& tokens,
                                           MacroScope& scope) {
    Expander expander(scope);
    std::vector<std::string_view> expanded;
    expander.expand(tokens, expanded);
    if (expander.failed()) return std::nullopt;
    return Evaluator(expanded).run();
}

}  // namespace varc::driver::projection
