// SPDX-License-Identifier: Apache-2.0
// Reads one program block's pragmas line by line into PassKeywords (behind parsePragmas).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "pragma/DeclaredSet.h"
#include "pragma/DirectiveForm.h"
#include "pragma/PragmaTokenizer.h"
#include "varc/core/Diagnostic.h"
#include "varc/core/PragmaLine.h"
#include "varc/variants/PassKeywords.h"
#include "varc/variants/Shortcuts.h"

namespace varc::variants {

class PragmaReader {
public:
    explicit PragmaReader(DiagnosticSink& sink) : mSink(sink) {}

    // Reads one pragma; reports problems with the line's own tokens at once.
    void read(const PragmaLine& line);
    // Applies the block-wide rules (procedural instancing, dynamic_branch precedence,
    // uniqueness). Returns nullopt if any error was reported since construction.
    std::optional<PassKeywords> finish();

private:
    void readKeywordSet(const DirectiveForm& form, const std::vector<PragmaToken>& tokens);
    bool readSetKeywords(const std::vector<PragmaToken>& tokens, DeclaredSet& set);
    void readUnknownShortcut(const std::vector<PragmaToken>& tokens);
    void warnUnknownShortcut(const PragmaToken& name);
    void warnUnknownOption(const PragmaToken& option, const std::string& directive);
    void readShortcut(const DirectiveForm& form, const std::vector<PragmaToken>& tokens);
    void readShortcutOptions(const std::vector<PragmaToken>& tokens, const Shortcut& shortcut,
                             std::vector<const ShortcutOption*>& options);
    void reportUnknownDirective(const PragmaToken& name, const std::vector<std::string>& known);
    void readEntry(std::string& entry, const std::vector<PragmaToken>& tokens);
    void readSkip(const std::vector<PragmaToken>& tokens);
    void readOther(const PragmaLine& line, const std::vector<PragmaToken>& tokens);
    void addProceduralInstancing();
    void error(SourceLocation location, std::string message,
               std::vector<DiagnosticNote> notes = {});

    DiagnosticSink& mSink;
    bool mFailed = false;
    SourceLocation mHash;  // the '#' of the line being read
    PassKeywords mResult;
    std::vector<DeclaredSet> mSets;
    std::vector<DeclaredSet> mBranches;
    std::map<std::string, SourceLocation> mShortcutsSeen;  // directive -> first location
    std::map<std::string, SourceLocation> mEntriesSeen;    // "vertex" -> first location
};

}  // namespace varc::variants
