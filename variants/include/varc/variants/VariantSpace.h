// SPDX-License-Identifier: Apache-2.0
// The variants of one pass: keyword table, counting without enumerating, ordered enumeration.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "varc/core/Diagnostic.h"
#include "varc/variants/PassKeywords.h"
#include "varc/variants/VariantKey.h"

namespace varc::variants {

// A pass's keyword table: every keyword its sets declare, sorted by name; index = VariantKey bit.
class KeywordTable {
public:
    explicit KeywordTable(std::vector<std::string> sortedUniqueNames);
    size_t size() const { return mNames.size(); }
    const std::string& name(size_t index) const { return mNames[index]; }
    const std::vector<std::string>& names() const { return mNames; }
    std::optional<size_t> indexOf(std::string_view name) const;

    // Keywords not declared by the pass are ignored (Unity: R = requested ∩ declared).
    VariantKey keyOf(const std::vector<std::string>& names) const;
    // Names of the keywords on in |key|, sorted.
    std::vector<std::string> namesOf(const VariantKey& key) const;

private:
    std::vector<std::string> mNames;
};

// The expanded variant space of a pass: the cartesian product of its sets, in Unity's order
// (first declared set varies slowest, options in declared order), minus skip_variants and the
// shortcuts' validity rules.
class VariantSpace {
public:
    // Reports an error (at the offending set) when the pass declares more than
    // VariantKey::kMaxKeywords keywords. Returns nullopt after reporting.
    static std::optional<VariantSpace> build(const PassKeywords& keywords, DiagnosticSink& sink);

    const KeywordTable& table() const { return mTable; }

    // Number of variants without enumerating them: the product over independent groups of sets,
    // enumerating only sets linked by validity rules. Saturates at UINT64_MAX.
    uint64_t count() const;
    // Number before skip_variants and rules ("Full variant space").
    uint64_t fullCount() const;

    // Calls |visit| for each variant in enumeration order; stop early by returning false.
    void forEach(const std::function<bool(const VariantKey&)>& visit) const;
    // All variants in enumeration order (use count() first; this allocates).
    std::vector<VariantKey> enumerate() const;

    // The sets after shortcut expansion and skip removal, as VariantKey options per set.
    const std::vector<std::vector<VariantKey>>& setOptions() const { return mSetOptions; }

private:
    VariantSpace(KeywordTable table) : mTable(std::move(table)) {}
    KeywordTable mTable;
    std::vector<std::vector<VariantKey>> mSetOptions;  // per set, declared order, skips removed
    std::vector<std::vector<VariantKey>> mFullSetOptions;
    struct Rule {
        VariantKey keyword, requiresAnyOf, forbids;
    };
    std::vector<Rule> mRules;
    friend class VariantSpaceBuilder;
};

}  // namespace varc::variants
