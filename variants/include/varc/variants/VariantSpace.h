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
    // |sortedUniqueNames| must be sorted, free of duplicates and at most kMaxKeywords long
    // (checked: violating it is a programmer error).
    explicit KeywordTable(std::vector<std::string> sortedUniqueNames);
    size_t size() const { return mNames.size(); }
    const std::string& name(size_t index) const { return mNames[index]; }
    const std::vector<std::string>& names() const { return mNames; }
    // The bit of |name|, or nullopt when the pass does not declare it. O(log n).
    std::optional<size_t> indexOf(std::string_view name) const;

    // Keywords not declared by the pass are ignored (Unity: R = requested ∩ declared).
    VariantKey keyOf(const std::vector<std::string>& names) const;
    // Names of the keywords on in |key|, sorted.
    std::vector<std::string> namesOf(const VariantKey& key) const;

    // The bit layout as a filament-style ASCII table, one row per keyword, e.g.
    //   +-----+-----------+
    //   | bit | keyword   |
    //   +-----+-----------+
    //   |   0 | FOG_EXP   |
    //   +-----+-----------+
    // An empty table yields the header rows only.
    std::string bitLayoutTable() const;

private:
    std::vector<std::string> mNames;
};

// The expanded variant space of a pass: the cartesian product of its sets, in Unity's order
// (first declared set varies slowest, options in declared order), minus skip_variants and the
// shortcuts' validity rules. Keywords removed by skip_variants are not in the table.
class VariantSpace {
public:
    // Reports an error (at the offending set) when the pass declares more than
    // VariantKey::kMaxKeywords keywords. Returns nullopt after reporting.
    static std::optional<VariantSpace> build(const PassKeywords& keywords, DiagnosticSink& sink);

    const KeywordTable& table() const { return mTable; }

    // Number of variants without enumerating them: the product over independent groups of sets,
    // enumerating only sets linked by validity rules. Saturates at UINT64_MAX.
    uint64_t count() const;
    // Number before skip_variants and rules ("Full variant space"). Saturates at UINT64_MAX.
    uint64_t fullCount() const { return mFullCount; }

    // Calls |visit| for each variant in enumeration order; stop early by returning false.
    void forEach(const std::function<bool(const VariantKey&)>& visit) const;
    // All variants in enumeration order (use count() first; this allocates).
    std::vector<VariantKey> enumerate() const;

    // One entry per PassKeywords::sets entry, same order: the set's options as VariantKeys in
    // declared order (the no-keyword entry is the empty key), skipped options removed.
    const std::vector<std::vector<VariantKey>>& setOptions() const { return mSetOptions; }

    // The option index (into setOptions()) of every set in |key|, or nullopt when |key| is not
    // one option per set: a bit no set has, two options of one set, or none of a set without
    // the no-keyword entry. Does not check the rules. Example: {"multi_compile _ A",
    // "multi_compile B C"}, key {A C} -> {1, 1}; key {A} -> nullopt.
    std::optional<std::vector<size_t>> optionsOf(const VariantKey& key) const;
    // Whether forEach() visits |key|. O(sets x options); no enumeration.
    bool contains(const VariantKey& key) const;

    // Some sets pinned to listed combinations of their options: |sets| are ascending set
    // indices; each combination holds one option index (into setOptions()) per entry of |sets|.
    struct Pins {
        std::vector<size_t> sets;
        std::vector<std::vector<size_t>> combinations;  // sorted lexicographically, unique
    };
    // The number of variants whose options at |sets| are |options| (a one-combination Pins),
    // counted like count(). Saturates at UINT64_MAX.
    uint64_t countPinned(const std::vector<size_t>& sets, const std::vector<size_t>& options) const;
    // forEach() restricted to variants whose options at |pins|.sets form one of its
    // combinations; same order as forEach(). Visits only the restricted variants' subtrees.
    void forEachPinned(const Pins& pins, const std::function<bool(const VariantKey&)>& visit) const;

private:
    explicit VariantSpace(KeywordTable table) : mTable(std::move(table)) {}

    // A ValidityRule over declared keywords. A variant with |keyword| on must have one bit of
    // |requiresAnyOf| on (when |hasRequirement|; an empty mask then means "never valid") and no
    // bit of |forbids|. Checked once the last set it mentions (|lastSet|) has been chosen.
    struct Rule {
        VariantKey keyword, requiresAnyOf, forbids;
        bool hasRequirement = false;
        size_t lastSet = 0;
    };
    using SetOptions = std::vector<std::vector<VariantKey>>;
    bool rulesHold(size_t set, const VariantKey& prefix) const;
    // Odometer over |sets| (ascending set indices) choosing from |options| (mSetOptions or a
    // pinned copy), pruning on rules; false = stopped early.
    bool walk(const SetOptions& options, const std::vector<size_t>& sets,
              const std::function<bool(const VariantKey&)>& visit) const;
    uint64_t countOver(const SetOptions& options) const;
    struct PinnedWalk;
    bool walkPinned(const PinnedWalk& walk, size_t set, const VariantKey& prefix, size_t first,
                    size_t last) const;

    KeywordTable mTable;
    std::vector<std::vector<VariantKey>> mSetOptions;  // per set, declared order, skips removed
    uint64_t mFullCount = 1;
    std::vector<Rule> mRules;
    std::vector<std::vector<size_t>> mRulesAtSet;    // per set: rules whose lastSet it is
    std::vector<std::vector<size_t>> mLinkedGroups;  // sets linked by rules, ascending
    std::vector<size_t> mFreeSets;                   // sets no rule mentions
    std::vector<size_t> mAllSets;                    // 0..n-1, for forEach
    friend class VariantSpaceBuilder;
};

}  // namespace varc::variants
