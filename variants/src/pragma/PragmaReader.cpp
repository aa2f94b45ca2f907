// SPDX-License-Identifier: Apache-2.0
// Reads one program block's pragmas line by line into PassKeywords (behind parsePragmas).
#include "pragma/PragmaReader.h"

#include <algorithm>

#include "pragma/DeclarationChecker.h"
#include "pragma/EditDistance.h"

namespace varc::variants {

namespace {

std::vector<std::string> shortcutDirectives() {
    std::vector<std::string> names;
    for (const Shortcut& shortcut : builtinShortcuts()) names.push_back(shortcut.directive());
    return names;
}

std::vector<std::string> optionNames() {
    std::vector<std::string> names;
    for (const ShortcutOption& option : shortcutOptions()) names.push_back(option.name);
    return names;
}

std::string didYouMean(std::string_view name, const std::vector<std::string>& candidates) {
    std::optional<std::string> suggestion = suggestName(name, candidates);
    return suggestion ? "; did you mean '" + *suggestion + "'?" : "";
}

std::vector<std::string> tokenTexts(const std::vector<PragmaToken>& tokens, size_t first) {
    std::vector<std::string> texts;
    for (size_t i = first; i < tokens.size(); ++i) texts.emplace_back(tokens[i].text);
    return texts;
}

}  // namespace

void PragmaReader::error(SourceLocation location, std::string message,
                         std::vector<DiagnosticNote> notes) {
    mFailed = true;
    mSink.report({Severity::Error, location, std::move(message), std::move(notes)});
}

void PragmaReader::read(const PragmaLine& line) {
    std::vector<PragmaToken> tokens = tokenizePragma(line);
    if (tokens.empty()) return;
    mHash = line.location;
    std::string_view name = tokens[0].text;
    DirectiveForm form = classifyDirective(name);
    switch (form.status) {
        case FormStatus::Set:
            return readKeywordSet(form, tokens);
        case FormStatus::Shortcut:
            return readShortcut(form, tokens);
        case FormStatus::UnknownSuffix:
            return reportUnknownDirective(tokens[0], keywordDirectiveSpellings());
        case FormStatus::StageOnDynamicBranch:
            return error(tokens[0].location,
                         "'" + std::string(name) + "': dynamic_branch takes no stage suffix");
        case FormStatus::NotKeywordDirective:
            break;
    }
    if (name == "vertex") return readEntry(mResult.vertexEntry, tokens);
    if (name == "fragment") return readEntry(mResult.fragmentEntry, tokens);
    if (name == "geometry") return readEntry(mResult.geometryEntry, tokens);
    if (name == "hull") return readEntry(mResult.hullEntry, tokens);
    if (name == "domain") return readEntry(mResult.domainEntry, tokens);
    if (name == "skip_variants") return readSkip(tokens);
    readOther(line, tokens);
}

void PragmaReader::readOther(const PragmaLine& line, const std::vector<PragmaToken>& tokens) {
    std::string_view name = tokens[0].text;
    auto append = [&](std::vector<std::string>& list) {
        std::vector<std::string> rest = tokenTexts(tokens, 1);
        list.insert(list.end(), rest.begin(), rest.end());
    };
    if (name == "exclude_renderers") return append(mResult.excludeRenderers);
    if (name == "only_renderers") return append(mResult.onlyRenderers);
    if (name == "instancing_options") return append(mResult.instancingOptions);
    if (name == "target") {
        if (tokens.size() < 2) return error(tokens[0].location, "'#pragma target' needs a value");
        std::string_view text = line.text;
        mResult.target = std::string(text.substr(tokens[1].text.data() - text.data()));
        return;
    }
    mResult.otherPragmas.push_back(line.text);
}

void PragmaReader::readKeywordSet(const DirectiveForm& form,
                                  const std::vector<PragmaToken>& tokens) {
    DeclaredSet set;
    set.decl.kind = form.kind;
    set.decl.local = form.local;
    set.decl.stages = form.stages;
    set.decl.directive = std::string(tokens[0].text);
    set.decl.location = mHash;
    set.directiveLocation = tokens[0].location;
    if (tokens.size() == 1) {
        return error(tokens[0].location,
                     "'#pragma " + set.decl.directive + "' declares no keywords");
    }
    if (!readSetKeywords(tokens, set)) return;
    // `shader_feature X` and `dynamic_branch X` mean `_ X`; `multi_compile X` stays always-on.
    bool single = set.decl.keywords.size() == 1 && !set.decl.keywords[0].empty();
    if (single && form.kind != DirectiveKind::MultiCompile) {
        set.decl.keywords.insert(set.decl.keywords.begin(), "");
        set.keywordLocations.insert(set.keywordLocations.begin(), tokens[0].location);
    }
    (form.kind == DirectiveKind::DynamicBranch ? mBranches : mSets).push_back(std::move(set));
}

bool PragmaReader::readSetKeywords(const std::vector<PragmaToken>& tokens, DeclaredSet& set) {
    bool ok = true;
    for (size_t i = 1; i < tokens.size(); ++i) {
        const PragmaToken& token = tokens[i];
        std::string keyword = isAllUnderscores(token.text) ? "" : std::string(token.text);
        // `#pragma multi_compile A B;` (C habit): the ';' is no part of the name.
        if (keyword.size() > 1 && keyword.back() == ';' &&
            isIdentifier(std::string_view(keyword).substr(0, keyword.size() - 1))) {
            keyword.pop_back();
            mSink.warning(token.location,
                          "';' after keyword '" + keyword + "' is not part of its name; ignored");
        }
        if (!keyword.empty() && !isIdentifier(keyword)) {
            error(token.location, "invalid keyword name '" + keyword +
                                      "': keywords must be identifiers ([A-Za-z_][A-Za-z0-9_]*)");
            ok = false;
            continue;
        }
        auto& keywords = set.decl.keywords;
        auto previous = std::find(keywords.begin(), keywords.end(), keyword);
        if (previous != keywords.end()) {
            SourceLocation first = set.keywordLocations[previous - keywords.begin()];
            error(token.location,
                  keyword.empty() ? "more than one no-keyword entry ('" + std::string(token.text) +
                                        "') in one set"
                                  : "keyword '" + keyword + "' appears twice in one set",
                  {{first, "first appears here"}});
            ok = false;
            continue;
        }
        keywords.push_back(keyword);
        set.keywordLocations.push_back(token.location);
    }
    return ok;
}

void PragmaReader::reportUnknownDirective(const PragmaToken& name,
                                          const std::vector<std::string>& known) {
    std::vector<std::string> candidates = known;
    std::vector<std::string> more = name.text.starts_with("multi_compile_")
                                        ? keywordDirectiveSpellings()
                                        : std::vector<std::string>{};
    candidates.insert(candidates.end(), more.begin(), more.end());
    std::string kind =
        name.text.starts_with("multi_compile_") ? "multi_compile shortcut" : "keyword directive";
    error(name.location, "unknown " + kind + " '" + std::string(name.text) + "'" +
                             didYouMean(name.text, candidates));
}

// Unity compiles shaders with a misspelt shortcut (`multi_compile_fwdbadd`): the pragma declares
// no keywords. varc does the same and says so. A misspelt directive followed by anything but
// shortcut options (`multi_compile_fragmnt _ A`) declares keywords the user wants: ignoring it
// would silently drop variants, so that stays an error.
void PragmaReader::readUnknownShortcut(const std::vector<PragmaToken>& tokens) {
    for (size_t i = 1; i < tokens.size(); ++i) {
        if (findShortcutOption(tokens[i].text) == nullptr) {
            return reportUnknownDirective(tokens[0], shortcutDirectives());
        }
    }
    warnUnknownShortcut(tokens[0]);
}

void PragmaReader::warnUnknownShortcut(const PragmaToken& name) {
    std::vector<std::string> candidates = shortcutDirectives();
    std::vector<std::string> more = keywordDirectiveSpellings();
    candidates.insert(candidates.end(), more.begin(), more.end());
    mSink.warning(name.location, "unknown multi_compile shortcut '" + std::string(name.text) +
                                     "' declares no keywords and is ignored, as in Unity" +
                                     didYouMean(name.text, candidates));
}

void PragmaReader::readShortcut(const DirectiveForm& form, const std::vector<PragmaToken>& tokens) {
    const Shortcut* shortcut = findShortcut(form.shortcutName);
    if (shortcut == nullptr) return readUnknownShortcut(tokens);
    std::string directive = shortcut->directive();
    auto [seen, inserted] = mShortcutsSeen.emplace(directive, tokens[0].location);
    if (!inserted) {
        // Unity compiles a shortcut written twice as if written once.
        mSink.report({Severity::Warning,
                      tokens[0].location,
                      "'" + directive + "' is declared twice; the repeat is ignored, as in Unity",
                      {{seen->second, "first declared here"}}});
        return;
    }
    std::vector<const ShortcutOption*> options;
    readShortcutOptions(tokens, *shortcut, options);
    ShortcutExpansion expansion = expandShortcut(*shortcut, options, mHash);
    for (KeywordSetDecl& decl : expansion.sets) {
        std::vector<SourceLocation> locations(decl.keywords.size(), tokens[0].location);
        mSets.push_back({std::move(decl), std::move(locations), tokens[0].location});
    }
    mResult.rules.insert(mResult.rules.end(), expansion.rules.begin(), expansion.rules.end());
}

// Options are validated against the global list; one that names no keyword of this shortcut
// is accepted with a warning (e.g. `multi_compile_fog novertexlight`), an unknown word is
// ignored with one (warnUnknownOption).
void PragmaReader::readShortcutOptions(const std::vector<PragmaToken>& tokens,
                                       const Shortcut& shortcut,
                                       std::vector<const ShortcutOption*>& options) {
    const std::string directive = shortcut.directive();
    for (size_t i = 1; i < tokens.size(); ++i) {
        const ShortcutOption* option = findShortcutOption(tokens[i].text);
        if (option == nullptr) {
            warnUnknownOption(tokens[i], directive);
            continue;
        }
        bool effective = false;
        for (const auto& set : shortcut.sets) {
            for (const std::string& keyword : option->removes) {
                effective |= std::find(set.begin(), set.end(), keyword) != set.end();
            }
        }
        if (!effective) {
            mSink.warning(tokens[i].location,
                          "option '" + option->name + "' has no effect on '" + directive + "'");
        }
        options.push_back(option);
    }
}

// Unity ignores a word after a shortcut that is not one of its options
// (`multi_compile_fwdadd fullshadows` declares what `multi_compile_fwdadd` does). varc too, and
// says so: often the word was meant as part of the shortcut's name.
void PragmaReader::warnUnknownOption(const PragmaToken& option, const std::string& directive) {
    std::vector<std::string> candidates = optionNames();
    std::string joined = directive + "_" + std::string(option.text);
    bool isShortcut = findShortcut(joined.substr(std::string("multi_compile_").size())) != nullptr;
    std::string hint = isShortcut ? "; did you mean '" + joined + "'?"
                                  : didYouMean(option.text, candidates);
    mSink.warning(option.location, "unknown option '" + std::string(option.text) + "' for '" +
                                       directive + "' is ignored, as in Unity" + hint);
}

void PragmaReader::readEntry(std::string& entry, const std::vector<PragmaToken>& tokens) {
    std::string stage(tokens[0].text);
    if (tokens.size() < 2)
        return error(tokens[0].location, "'#pragma " + stage + "' needs a function name");
    if (tokens.size() > 2) {
        return error(tokens[2].location, "unexpected '" + std::string(tokens[2].text) +
                                             "' after '#pragma " + stage + " " +
                                             std::string(tokens[1].text) + "'");
    }
    auto [seen, inserted] = mEntriesSeen.emplace(stage, tokens[1].location);
    if (!inserted && entry != tokens[1].text) {
        return error(tokens[1].location,
                     "'#pragma " + stage + " " + std::string(tokens[1].text) +
                         "' conflicts with the earlier '" + entry + "'",
                     {{seen->second, "first declared here"}});
    }
    entry = std::string(tokens[1].text);
}

void PragmaReader::readSkip(const std::vector<PragmaToken>& tokens) {
    if (tokens.size() == 1) {
        mSink.warning(tokens[0].location, "'#pragma skip_variants' lists no keywords");
    }
    for (size_t i = 1; i < tokens.size(); ++i) {
        if (!isIdentifier(tokens[i].text) || isAllUnderscores(tokens[i].text)) {
            error(tokens[i].location,
                  "invalid keyword name '" + std::string(tokens[i].text) + "' in skip_variants");
            continue;
        }
        mResult.skipped.emplace_back(tokens[i].text);
    }
}

// `instancing_options procedural:Fn` anywhere in the block adds PROCEDURAL_INSTANCING_ON to the
// multi_compile_instancing set (docs/KEYWORDS.md §4: 3 variants with procedural instancing).
void PragmaReader::addProceduralInstancing() {
    bool procedural =
        std::any_of(mResult.instancingOptions.begin(), mResult.instancingOptions.end(),
                    [](const std::string& option) { return option.starts_with("procedural:"); });
    if (!procedural) return;
    for (DeclaredSet& set : mSets) {
        if (set.decl.directive != "multi_compile_instancing") continue;
        set.decl.keywords.push_back("PROCEDURAL_INSTANCING_ON");
        set.keywordLocations.push_back(set.directiveLocation);
    }
}

std::optional<PassKeywords> PragmaReader::finish() {
    addProceduralInstancing();
    DeclarationChecker checker(mSink);
    checker.resolveDynamicBranches(mSets, mBranches);
    checker.mergeIdenticalSets(mSets);
    bool unique = checker.checkUnique(mSets);
    unique = checker.checkUnique(mBranches) && unique;
    if (mFailed || !unique) return std::nullopt;
    for (DeclaredSet& set : mSets) mResult.sets.push_back(std::move(set.decl));
    for (DeclaredSet& set : mBranches) mResult.dynamicBranches.push_back(std::move(set.decl));
    return std::move(mResult);
}

}  // namespace varc::variants
