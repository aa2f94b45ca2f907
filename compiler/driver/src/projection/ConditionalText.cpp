// SPDX-License-Identifier: Apache-2.0
// Parses a program text into its directives and the keywords its other lines can name.
#include "ConditionalText.h"

#include "BraceShape.h"
#include "DefineGroups.h"

namespace varc::driver::projection {

namespace {

bool isIdentStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool isIdentChar(char c) { return isIdentStart(c) || (c >= '0' && c <= '9'); }
bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// Phase 2 of C: a backslash before a newline joins the lines.
std::string splice(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '\\') {
            size_t j = i + 1;
            if (j < text.size() && text[j] == '\r') ++j;
            if (j < text.size() && text[j] == '\n') {
                i = j;
                continue;
            }
        }
        out += text[i];
    }
    return out;
}

// Phase 3: comments become blanks, newlines stay (so lines keep their count). Per line: whether
// it starts inside a block comment.
std::vector<char> blankComments(std::string& text) {
    std::vector<char> startsInComment{0};
    bool block = false, line = false, string = false;
    for (size_t i = 0; i < text.size(); ++i) {
        char& c = text[i];
        if (c == '\n') {
            line = string = false;
            startsInComment.push_back(block ? 1 : 0);
            continue;
        }
        if (block) {
            if (c == '*' && i + 1 < text.size() && text[i + 1] == '/') {
                text[i + 1] = ' ';
                block = false;
                ++i;
            }
            c = ' ';
        } else if (line) {
            c = ' ';
        } else if (string) {
            if (c == '"') string = false;
        } else if (c == '"') {
            string = true;
        } else if (c == '/' && i + 1 < text.size() && (text[i + 1] == '/' || text[i + 1] == '*')) {
            (text[i + 1] == '/' ? line : block) = true;
            text[i + 1] = ' ';
            c = ' ';
            ++i;
        }
    }
    return startsInComment;
}

size_t skipBlanks(std::string_view text, size_t i) {
    while (i < text.size() && isBlank(text[i])) ++i;
    return i;
}

bool isBlankLine(std::string_view line) { return skipBlanks(line, 0) == line.size(); }

PpLine::Kind directiveKind(std::string_view name) {
    using Kind = PpLine::Kind;
    if (name == "if") return Kind::If;
    if (name == "ifdef") return Kind::Ifdef;
    if (name == "ifndef") return Kind::Ifndef;
    if (name == "elif") return Kind::Elif;
    if (name == "else") return Kind::Else;
    if (name == "endif") return Kind::Endif;
    if (name == "define") return Kind::Define;
    if (name == "undef") return Kind::Undef;
    if (name == "pragma") return Kind::Pragma;
    return Kind::Other;
}

// Directives whose meaning a block comment continued onto the next line could change.
bool isConditionOrDefinition(PpLine::Kind kind) {
    using Kind = PpLine::Kind;
    return kind == Kind::If || kind == Kind::Ifdef || kind == Kind::Ifndef || kind == Kind::Elif ||
           kind == Kind::Define || kind == Kind::Undef;
}

}  // namespace

bool isIdentifierToken(std::string_view token) { return !token.empty() && isIdentStart(token[0]); }

std::vector<std::string_view> ppTokens(std::string_view text) {
    static constexpr std::string_view kPairs[] = {
        "##", "&&", "||", "==", "!=", "<=", ">=", "<<", ">>"};
    std::vector<std::string_view> tokens;
    for (size_t i = 0; i < text.size();) {
        const char c = text[i];
        size_t end = i + 1;
        if (isBlank(c) || c == '\n') {
            ++i;
            continue;
        }
        if (isIdentStart(c)) {
            while (end < text.size() && isIdentChar(text[end])) ++end;
        } else if ((c >= '0' && c <= '9') ||
                   (c == '.' && end < text.size() && text[end] >= '0' && text[end] <= '9')) {
            while (end < text.size() && (isIdentChar(text[end]) || text[end] == '.')) ++end;
        } else if (c == '"') {
            while (end < text.size() && text[end] != '"') ++end;
            end = std::min(end + 1, text.size());
        } else {
            for (std::string_view pair : kPairs) {
                if (text.substr(i, 2) == pair) end = i + 2;
            }
        }
        tokens.push_back(text.substr(i, end - i));
        i = end;
    }
    return tokens;
}

ConditionalText::ConditionalText(std::string_view text, const std::vector<std::string>& keywords)
    : mText(splice(text)), mKeywordNames(keywords) {
    for (size_t k = 0; k < mKeywordNames.size(); ++k)
        mKeywords.emplace(mKeywordNames[k], static_cast<int>(k));
    std::vector<char> startsInComment = blankComments(mText);
    std::vector<std::string_view> lines;
    std::string_view all = mText;
    for (size_t start = 0; start <= all.size();) {
        size_t end = all.find('\n', start);
        if (end == std::string_view::npos) end = all.size();
        lines.push_back(all.substr(start, end - start));
        start = end + 1;
    }
    classify(lines, startsInComment);
    if (mUsable) linkConditionals();
    if (mUsable) {
        mBraceMacros = unbalancedBraceMacros(mLines);
        markCleanGroups(mLines, mBraceMacros);
        markDefineGroups(mLines);
    }
}

int ConditionalText::keywordIndex(std::string_view name) const {
    auto it = mKeywords.find(name);
    return it == mKeywords.end() ? -1 : it->second;
}

void ConditionalText::classify(const std::vector<std::string_view>& lines,
                               const std::vector<char>& startsInComment) {
    std::vector<std::vector<std::string_view>> identifiers;  // per PpLine (Other; Text: code)
    for (size_t n = 0; n < lines.size(); ++n) {
        std::string_view line = lines[n];
        size_t hash = skipBlanks(line, 0);
        bool directive = hash < line.size() && line[hash] == '#';
        if (directive && startsInComment[n]) {
            // `*/ #if`: C reads no directive here; do not guess what glslang reads.
            mUsable = false;
            return;
        }
        if (!directive) {
            if (mLines.empty() || mLines.back().kind != PpLine::Kind::Text) {
                mLines.emplace_back();
                identifiers.emplace_back();
            }
            for (std::string_view token : ppTokens(line)) mLines.back().code.push_back(token);
            continue;
        }
        size_t nameStart = skipBlanks(line, hash + 1), nameEnd = nameStart;
        while (nameEnd < line.size() && isIdentChar(line[nameEnd])) ++nameEnd;
        PpLine parsed;
        parsed.kind = directiveKind(line.substr(nameStart, nameEnd - nameStart));
        identifiers.emplace_back();
        if (parsed.kind == PpLine::Kind::Other) {
            for (std::string_view token : ppTokens(line.substr(nameEnd)))
                if (isIdentifierToken(token)) identifiers.back().push_back(token);
        }
        parseDirective(line.substr(nameStart, nameEnd - nameStart), line.substr(nameEnd), parsed);
        // A block comment opened on this line and closed on a later one with tokens after it:
        // C would join those tokens to the directive.
        if (isConditionOrDefinition(parsed.kind) && n + 1 < lines.size() &&
            startsInComment[n + 1]) {
            size_t last = n + 1;
            while (last + 1 < lines.size() && startsInComment[last + 1]) ++last;
            if (!isBlankLine(lines[last])) mUsable = false;
        }
        mLines.push_back(std::move(parsed));
    }
    resolveReferences(identifiers);
}

void ConditionalText::parseDirective(std::string_view directive, std::string_view rest,
                                     PpLine& line) {
    using Kind = PpLine::Kind;
    (void)directive;
    switch (line.kind) {
        case Kind::If:
        case Kind::Elif:
            line.tokens = ppTokens(rest);
            break;
        case Kind::Ifdef:
        case Kind::Ifndef:
        case Kind::Undef: {
            std::vector<std::string_view> tokens = ppTokens(rest);
            if (tokens.empty() || !isIdentifierToken(tokens[0])) mUsable = false;
            if (!tokens.empty()) line.name = tokens[0];
            break;
        }
        case Kind::Define: {
            size_t start = skipBlanks(rest, 0), end = start;
            while (end < rest.size() && isIdentChar(rest[end])) ++end;
            line.name = rest.substr(start, end - start);
            if (line.name.empty() || !isIdentStart(line.name[0])) mUsable = false;
            std::string_view body = rest.substr(end);
            if (!body.empty() && body[0] == '(') {
                line.functionLike = true;
                size_t close = body.find(')');
                if (close == std::string_view::npos) {
                    mUsable = false;
                    break;
                }
                for (std::string_view token : ppTokens(body.substr(1, close - 1)))
                    if (token != ",") line.params.push_back(token);
                body = body.substr(close + 1);
            }
            line.tokens = ppTokens(body);
            break;
        }
        default:
            break;
    }
}

void ConditionalText::linkConditionals() {
    using Kind = PpLine::Kind;
    std::vector<std::vector<uint32_t>> groups;  // open groups: their branch directives
    for (uint32_t i = 0; i < mLines.size(); ++i) {
        Kind kind = mLines[i].kind;
        if (kind == Kind::If || kind == Kind::Ifdef || kind == Kind::Ifndef) {
            groups.push_back({i});
        } else if (kind == Kind::Elif || kind == Kind::Else || kind == Kind::Endif) {
            if (groups.empty() ||
                (kind != Kind::Endif && mLines[groups.back().back()].kind == Kind::Else)) {
                mUsable = false;  // no open group, or a branch after #else
                return;
            }
            mLines[groups.back().back()].next = i;
            groups.back().push_back(i);
            if (kind == Kind::Endif) {
                for (uint32_t branch : groups.back()) mLines[branch].end = i;
                groups.pop_back();
            }
        }
    }
    if (!groups.empty()) mUsable = false;
}

// The keywords each name can reach through #define bodies (any definition of the text: a
// superset of the one in force when a line expands it), then per Text/Other line.
void ConditionalText::resolveReferences(const std::vector<std::vector<std::string_view>>& idents) {
    std::unordered_map<std::string_view, std::vector<std::string_view>> bodies;
    for (const PpLine& line : mLines) {
        if (line.kind != PpLine::Kind::Define) continue;
        std::vector<std::string_view>& body = bodies[line.name];
        for (std::string_view token : line.tokens)
            if (isIdentifierToken(token)) body.push_back(token);
    }
    std::unordered_map<std::string_view, KeywordBits> reach;
    for (const auto& [name, body] : bodies) {
        KeywordBits& bits = reach[name];
        for (std::string_view token : body)
            if (int k = keywordIndex(token); k >= 0) bits.set(static_cast<size_t>(k));
    }
    for (bool changed = true; changed;) {  // to the fixed point: chains of macros
        changed = false;
        for (const auto& [name, body] : bodies) {
            KeywordBits bits = reach[name];
            for (std::string_view token : body)
                if (auto it = reach.find(token); it != reach.end()) bits |= it->second;
            if (bits != reach[name]) {
                reach[name] = bits;
                changed = true;
            }
        }
    }
    for (size_t i = 0; i < mLines.size(); ++i) {
        const bool text = mLines[i].kind == PpLine::Kind::Text;
        for (std::string_view token : text ? mLines[i].code : idents[i]) {
            if (!isIdentifierToken(token)) continue;
            if (int k = keywordIndex(token); k >= 0) mLines[i].refs.set(static_cast<size_t>(k));
            if (auto it = reach.find(token); it != reach.end()) mLines[i].refs |= it->second;
        }
    }
}

}  // namespace varc::driver::projection
