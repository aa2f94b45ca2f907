// SPDX-License-Identifier: Apache-2.0
// Prunes a preprocessed program to the code one stage's entry point reaches.
#include "varc/frontend/StagePruner.h"

#include <algorithm>
#include <optional>
#include <unordered_map>

#include "pruner/Declaration.h"
#include "pruner/DeclarationClassifier.h"
#include "pruner/DeclarationSplitter.h"
#include "pruner/LineOriginMap.h"
#include "pruner/PrunedTextWriter.h"
#include "pruner/ShaderTokenizer.h"

namespace varc::frontend {
namespace {

using pruner::Declaration;
using pruner::DeclarationKind;
using pruner::Retention;

PruneResult fallBack(std::string_view preprocessed) {
    return PruneResult{std::string(preprocessed), false, {}};
}

std::optional<std::vector<Declaration>> parseDeclarations(const pruner::ShaderTokenizer& tokenizer,
                                                          ShaderDialect dialect) {
    const std::optional<std::vector<pruner::DeclarationSpan>> spans =
        pruner::DeclarationSplitter(tokenizer.tokens(), dialect).split();
    if (!spans) return std::nullopt;
    const pruner::DeclarationClassifier classifier(tokenizer.tokens(), dialect);
    std::vector<Declaration> declarations;
    declarations.reserve(spans->size());
    for (const pruner::DeclarationSpan& span : *spans) {
        declarations.push_back(classifier.classify(span));
    }
    return declarations;
}

bool definesEntry(const Declaration& decl, std::string_view entryPoint) {
    return decl.kind == DeclarationKind::Function && decl.defines.front() == entryPoint;
}

// Marks what must be kept: the roots (entry point overloads and Always declarations), then
// everything their uses name, transitively; the first reached loose HLSL uniform pulls in all of
// them. Returns nullopt when |entryPoint| has no definition.
std::optional<std::vector<bool>> markReachable(const std::vector<Declaration>& declarations,
                                               std::string_view entryPoint) {
    std::unordered_map<std::string_view, std::vector<size_t>> byName;
    std::vector<size_t> pending;
    bool entryDefined = false;
    for (size_t i = 0; i < declarations.size(); ++i) {
        const Declaration& decl = declarations[i];
        for (const std::string_view name : decl.defines) byName[name].push_back(i);
        if (definesEntry(decl, entryPoint)) entryDefined = entryDefined || decl.hasBody;
        if (decl.retention == Retention::Always || definesEntry(decl, entryPoint)) {
            pending.push_back(i);
        }
    }
    if (!entryDefined) return std::nullopt;

    std::vector<bool> kept(declarations.size(), false);
    bool globalGroupKept = false;
    while (!pending.empty()) {
        const size_t index = pending.back();
        pending.pop_back();
        if (kept[index]) continue;
        kept[index] = true;
        const Declaration& decl = declarations[index];
        if (decl.retention == Retention::GlobalGroup && !globalGroupKept) {
            globalGroupKept = true;
            for (size_t i = 0; i < declarations.size(); ++i) {
                if (declarations[i].retention == Retention::GlobalGroup) pending.push_back(i);
            }
        }
        for (const std::string_view name : decl.uses) {
            const auto found = byName.find(name);
            if (found == byName.end()) continue;
            for (const size_t target : found->second) {
                if (!kept[target] && declarations[target].retention != Retention::Never) {
                    pending.push_back(target);
                }
            }
        }
    }
    return kept;
}

std::vector<std::string> keptFunctionNames(const std::vector<const Declaration*>& kept) {
    std::vector<std::string> names;
    for (const Declaration* decl : kept) {
        if (decl->kind != DeclarationKind::Function) continue;
        const std::string name(decl->defines.front());
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
    return names;
}

}  // namespace

PruneResult pruneToEntryPoint(std::string_view preprocessed, std::string_view entryPoint,
                              ShaderDialect dialect) {
    pruner::ShaderTokenizer tokenizer;
    if (!tokenizer.tokenize(preprocessed)) return fallBack(preprocessed);
    pruner::LineOriginMap origins;
    if (!origins.build(tokenizer.directives(), tokenizer.lineCount())) {
        return fallBack(preprocessed);
    }
    const std::optional<std::vector<Declaration>> declarations =
        parseDeclarations(tokenizer, dialect);
    if (!declarations) return fallBack(preprocessed);
    const std::optional<std::vector<bool>> reachable = markReachable(*declarations, entryPoint);
    if (!reachable) return fallBack(preprocessed);

    std::vector<const Declaration*> kept;
    for (size_t i = 0; i < declarations->size(); ++i) {
        if ((*reachable)[i]) kept.push_back(&(*declarations)[i]);
    }
    PruneResult result;
    result.text = pruner::PrunedTextWriter(tokenizer, origins).write(kept);
    result.pruned = true;
    result.keptFunctions = keptFunctionNames(kept);
    return result;
}

}  // namespace varc::frontend
