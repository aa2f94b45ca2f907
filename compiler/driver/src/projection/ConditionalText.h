// SPDX-License-Identifier: Apache-2.0
// A program text as its preprocessor directives and the keyword macros its other lines can name:
// what the keyword projection walks once per distinct projection instead of the whole text.
#pragma once

#include <bitset>
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "varc/variants/VariantKey.h"

namespace varc::driver::projection {

using KeywordBits = std::bitset<variants::VariantKey::kMaxKeywords>;

// One logical line (joined at `\` newlines, comments blanked), or a run of non-directive lines.
struct PpLine {
    enum class Kind { Text, If, Ifdef, Ifndef, Elif, Else, Endif, Define, Undef, Pragma, Other };
    Kind kind = Kind::Text;
    std::string_view name;                 // #ifdef, #ifndef, #define, #undef: the macro
    std::vector<std::string_view> tokens;  // #if, #elif: the expression; #define: the body
    std::vector<std::string_view> params;  // #define NAME(params)
    bool functionLike = false;
    // Text and Other: the keywords its identifiers name, directly or through the body of any
    // #define of the text (whichever is in force: a superset of what expansion looks up).
    KeywordBits refs;
    uint32_t next = 0;  // #if/#elif/#else: the group's next branch directive (or its #endif)
    uint32_t end = 0;   // #if/#elif/#else: the group's #endif
    // Text: every preprocessing token of the run, in order (what BlockTracker follows).
    std::vector<std::string_view> code;
    // #if/#ifdef/#ifndef: whichever branches a variant takes, the group changes nothing but the
    // text between its braces (BraceShape.h): no directive other than conditionals, and braces
    // that balance in every branch without closing one opened before the group.
    bool clean = false;
    // #if/#ifdef/#ifndef: every branch, nested groups included, holds only #define/#undef lines
    // and blank text (DefineGroups.h). Then |defines| lists their names, once each.
    bool definesOnly = false;
    std::vector<std::string_view> defines;
};

// The directive structure of a text, parsed once per pass and shared by its stages' walks.
class ConditionalText {
public:
    // |keywords|: the pass's keyword table (index = VariantKey bit).
    ConditionalText(std::string_view text, const std::vector<std::string>& keywords);
    ConditionalText(const ConditionalText&) = delete;  // lines point into mText
    ConditionalText& operator=(const ConditionalText&) = delete;

    // False when the text has a shape the analysis does not model (unbalanced conditionals, a
    // directive continued by a block comment): every keyword is then taken as observed.
    bool usable() const { return mUsable; }
    const std::vector<PpLine>& lines() const { return mLines; }
    // The bit of keyword |name|, or -1.
    int keywordIndex(std::string_view name) const;
    // Macros some definition of which can expand to braces that do not balance (BraceShape.h).
    const std::unordered_set<std::string_view>& braceMacros() const { return mBraceMacros; }

private:
    void classify(const std::vector<std::string_view>& lines,
                  const std::vector<char>& startsInComment);
    void parseDirective(std::string_view directive, std::string_view rest, PpLine& line);
    void linkConditionals();
    void resolveReferences(const std::vector<std::vector<std::string_view>>& identifiers);

    std::string mText;  // spliced, comments blanked: every string_view points here
    std::vector<PpLine> mLines;
    std::unordered_map<std::string_view, int> mKeywords;
    std::vector<std::string> mKeywordNames;
    std::unordered_set<std::string_view> mBraceMacros;
    bool mUsable = true;
};

// The preprocessing tokens of |text|: identifiers, pp-numbers, strings, punctuators (`##`,
// `&&`, `||`, `==`, `!=`, `<=`, `>=`, `<<`, `>>` as one token, others one character each).
std::vector<std::string_view> ppTokens(std::string_view text);

bool isIdentifierToken(std::string_view token);

}  // namespace varc::driver::projection
