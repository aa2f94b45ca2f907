// SPDX-License-Identifier: Apache-2.0
// Top-level blocks of a walk's emitted text, function bodies named from their headers.
#include "BlockTracker.h"

#include <algorithm>

namespace varc::driver::projection {

namespace {

bool isIdentStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool isIdentChar(char c) { return isIdentStart(c) || (c >= '0' && c <= '9'); }

// Words that make a header declare a type or a buffer, not a function.
bool declaresNonFunction(std::string_view word) {
    return word == "struct" || word == "class" || word == "interface" || word == "namespace" ||
           word == "cbuffer" || word == "tbuffer" || word == "typedef";
}

// Where in a header `... name(params) [: SEMANTIC]` the defined function's name is, or npos.
size_t functionNameIndex(const std::vector<std::string_view>& header) {
    if (std::any_of(header.begin(), header.end(), declaresNonFunction))
        return std::string_view::npos;
    size_t end = header.size();
    if (end >= 2 && header[end - 2] == ":" && isIdentifierToken(header[end - 1])) end -= 2;
    if (end == 0 || header[end - 1] != ")") return std::string_view::npos;
    int parens = 0;
    for (size_t i = end; i-- > 0;) {
        if (header[i] == ")") ++parens;
        if (header[i] != "(" || --parens != 0) continue;
        if (i == 0 || !isIdentifierToken(header[i - 1])) break;
        if (i >= 2 && header[i - 2] == ":") break;  // `: register(b0)`
        // `x = f(...)`: an initializer calls f, it does not define it.
        if (std::find(header.begin(), header.begin() + static_cast<long>(i), "=") !=
            header.begin() + static_cast<long>(i))
            break;
        return i - 1;
    }
    return std::string_view::npos;
}

// The identifiers a string literal spells: a name an attribute gives as text
// (`patchconstantfunc("Patch")`) still counts as used.
template <typename Sink>
void identifiersInString(std::string_view literal, Sink&& sink) {
    for (size_t i = 0; i < literal.size();) {
        if (!isIdentStart(literal[i])) {
            ++i;
            continue;
        }
        size_t end = i + 1;
        while (end < literal.size() && isIdentChar(literal[end])) ++end;
        sink(literal.substr(i, end - i));
        i = end;
    }
}

}  // namespace

int BlockTracker::follow(const std::vector<std::string_view>& code,
                         const Definitions& definitions) {
    const int body = functionBody();
    mClosed = false;
    for (std::string_view t : code) token(t, definitions);
    return body >= 0 && !mClosed && mCurrent == body ? body : -1;
}

int BlockTracker::functionBody() const {
    if (mCurrent < 0 || mBlocks[static_cast<size_t>(mCurrent)].function.empty()) return -1;
    return mCurrent;
}

void BlockTracker::finish() { flushHeader(std::string_view::npos); }

void BlockTracker::token(std::string_view t, const Definitions& definitions) {
    if (t == "{" || t == "}") {
        brace(t, false);
        return;
    }
    if (mDepth == 0) {
        mHeader.push_back(t);
        if (t == ";") flushHeader(std::string_view::npos);  // a prototype's name counts as used
    } else if (isIdentifierToken(t)) {
        identifier(t);
    } else if (t.front() == '"') {
        identifiersInString(t, [this](std::string_view name) { identifier(name); });
    }
    if (isIdentifierToken(t) && mBraceMacros.count(t)) {
        mBraceUses.push_back(t);
        mExpansionBudget = kExpansionBudget;
        expand(t, definitions, 0);
    }
}

void BlockTracker::brace(std::string_view t, bool fromMacro) {
    if (t == "{") {
        if (mDepth++ > 0) return;
        const size_t name = fromMacro ? std::string_view::npos : functionNameIndex(mHeader);
        const std::string_view function =
            name == std::string_view::npos ? std::string_view() : mHeader[name];
        flushHeader(name);
        mBlocks.push_back({function, {}});
        mCurrent = static_cast<int>(mBlocks.size() - 1);
        return;
    }
    if (mDepth == 0) {
        mConsistent = false;
        return;
    }
    if (--mDepth == 0) {
        mCurrent = -1;
        mClosed = true;
    }
}

// The header's identifiers are used by what follows, except the function name at |skip|.
void BlockTracker::flushHeader(size_t skip) {
    for (size_t i = 0; i < mHeader.size(); ++i) {
        std::string_view t = mHeader[i];
        if (i == skip) continue;
        if (isIdentifierToken(t))
            mOutside.push_back(t);
        else if (t.front() == '"')
            identifiersInString(t, [this](std::string_view name) { mOutside.push_back(name); });
    }
    mHeader.clear();
}

void BlockTracker::identifier(std::string_view name) {
    if (int body = functionBody(); body >= 0)
        mBlocks[static_cast<size_t>(body)].identifiers.push_back(name);
    else
        mOutside.push_back(name);
}

// The braces |macro|'s definition in force expands to, through the macros it names. Macros
// nesting too deep or expanding to too much (a fan-out attack) leave the braces unknown.
void BlockTracker::expand(std::string_view macro, const Definitions& definitions, int depth) {
    const PpLine* definition = definitions(macro);
    if (!definition) return;
    if (depth > 64 || mExpansionBudget < definition->tokens.size()) {
        mConsistent = false;
        return;
    }
    mExpansionBudget -= definition->tokens.size();
    for (std::string_view t : definition->tokens) {
        if (!mConsistent) return;
        if (t == "{" || t == "}")
            brace(t, true);
        else if (t != macro && mBraceMacros.count(t))
            expand(t, definitions, depth + 1);
    }
}

}  // namespace varc::driver::projection
