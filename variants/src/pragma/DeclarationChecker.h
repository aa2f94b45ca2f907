// SPDX-License-Identifier: Apache-2.0
// Block-wide keyword rules: dynamic_branch precedence, repeated sets, keywords in two sets.
#pragma once

#include <vector>

#include "pragma/DeclaredSet.h"
#include "varc/core/Diagnostic.h"

namespace varc::variants {

// Runs after every pragma of a block has been read, because Unity's rules do not depend on
// the order of the lines (docs/KEYWORDS.md, "Errors").
class DeclarationChecker {
public:
    explicit DeclarationChecker(DiagnosticSink& sink) : mSink(sink) {}

    // dynamic_branch wins: removes from |sets| every keyword that |branches| also declare,
    // warning at the removed keyword with a note at the dynamic_branch. A set left without any
    // keyword is dropped. Example: `multi_compile _ A` + `dynamic_branch A` -> no variant set.
    void resolveDynamicBranches(std::vector<DeclaredSet>& sets,
                                const std::vector<DeclaredSet>& branches);

    // Drops from |sets| each set identical to an earlier one (same keywords in any order, same
    // kind, scope and stages) with a note: Unity merges them. Example: `multi_compile_fwdbase`
    // then `multi_compile _ VERTEXLIGHT_ON` -> one VERTEXLIGHT_ON set.
    void mergeIdenticalSets(std::vector<DeclaredSet>& sets);

    // Reports a set repeated (same keywords in any order) and a keyword declared by two sets,
    // each with a note at the first declaration. Returns false after reporting an error.
    bool checkUnique(const std::vector<DeclaredSet>& sets);

private:
    bool isRepeatedSet(const std::vector<DeclaredSet>& sets, size_t index);
    bool checkKeywordsUnique(const std::vector<DeclaredSet>& sets,
                             const std::vector<bool>& repeated);
    DiagnosticSink& mSink;
};

}  // namespace varc::variants
