// SPDX-License-Identifier: Apache-2.0
// The largest variant space a command enumerates.
#include "varc/frontend/VariantLimit.h"

#include <algorithm>
#include <string>
#include <vector>

#include "varc/variants/PassKeywords.h"

namespace varc::frontend {

namespace {

std::string spelled(const variants::KeywordSetDecl& set) {
    std::string text = set.directive;
    for (const std::string& keyword : set.keywords) text += " " + (keyword.empty() ? "_" : keyword);
    return text;
}

}  // namespace

bool checkVariantLimit(const LoadedShader& shader, const LoadedPass& pass, uint64_t limit,
                       DiagnosticSink& sink) {
    // With a project's plan the limit applies to what its materials select, not to the
    // declared space (a 10^12-variant uber shader with five materials builds).
    uint64_t count = pass.plan ? pass.plan->counts.materials : pass.space->count();
    if (count <= limit) return true;
    const std::vector<variants::KeywordSetDecl>& sets = pass.keywords.sets;
    std::vector<size_t> order(sets.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&sets](size_t a, size_t b) {
        return sets[a].keywords.size() > sets[b].keywords.size();
    });
    std::vector<DiagnosticNote> notes;
    for (size_t i = 0; i < std::min<size_t>(3, order.size()); ++i) {
        const variants::KeywordSetDecl& set = sets[order[i]];
        notes.push_back({set.location, "a set of " + std::to_string(set.keywords.size()) +
                                           " options: " + spelled(set)});
    }
    sink.report({Severity::Error,
                 pass.pass->program->origin,
                 describePass(shader.ast, *pass.pass, pass.index) + " has " +
                     std::to_string(count) + " variants (" + std::to_string(sets.size()) +
                     " keyword sets" + (pass.plan ? ", selected by the project's materials" : "") +
                     "); the limit is " + std::to_string(limit) +
                     " (--max-variants): use shader_feature for material keywords, "
                     "skip_variants, or fewer sets",
                 std::move(notes)});
    return false;
}

}  // namespace varc::frontend
