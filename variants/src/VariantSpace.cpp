// SPDX-License-Identifier: Apache-2.0
// VariantSpace: counting by independent groups, and the pruned odometer that enumerates.
#include "varc/variants/VariantSpace.h"

#include <algorithm>
#include <cstdint>

#include "VariantSpaceBuilder.h"
#include "varc/core/Check.h"
#include "varc/core/SaturatingMath.h"

namespace varc::variants {

namespace {

constexpr size_t kUnpinned = SIZE_MAX;

bool intersects(const VariantKey& a, const VariantKey& b) {
    const auto& x = a.words();
    const auto& y = b.words();
    return ((x[0] & y[0]) | (x[1] & y[1]) | (x[2] & y[2]) | (x[3] & y[3])) != 0;
}

}  // namespace

std::optional<VariantSpace> VariantSpace::build(const PassKeywords& keywords,
                                                DiagnosticSink& sink) {
    return VariantSpaceBuilder::build(keywords, sink);
}

bool VariantSpace::rulesHold(size_t set, const VariantKey& prefix) const {
    for (size_t index : mRulesAtSet[set]) {
        const Rule& rule = mRules[index];
        if (!intersects(prefix, rule.keyword)) continue;
        if (rule.hasRequirement && !intersects(prefix, rule.requiresAnyOf)) return false;
        if (intersects(prefix, rule.forbids)) return false;
    }
    return true;
}

// Nested loops over |sets| with the last set fastest, written as an odometer. prefix[d + 1] is
// the key of the options chosen for sets[0..d]; a rule is checked at the set that completes
// it, so an invalid prefix skips its whole subtree.
// Example: lightpass visits 40 leaves at most, keeps 13.
bool VariantSpace::walk(const SetOptions& options, const std::vector<size_t>& sets,
                        const std::function<bool(const VariantKey&)>& visit) const {
    if (sets.empty()) return visit(VariantKey{});
    for (size_t set : sets) {
        if (options[set].empty()) return true;
    }
    const size_t n = sets.size();
    std::vector<size_t> choice(n, 0);
    std::vector<VariantKey> prefix(n + 1);
    size_t depth = 0;
    while (true) {
        prefix[depth + 1] = prefix[depth] | options[sets[depth]][choice[depth]];
        if (rulesHold(sets[depth], prefix[depth + 1])) {
            if (depth + 1 < n) {
                choice[++depth] = 0;
                continue;
            }
            if (!visit(prefix[n])) return false;
        }
        while (++choice[depth] == options[sets[depth]].size()) {
            if (depth == 0) return true;
            --depth;
        }
    }
}

// Sets that no rule links multiply; each rule-linked group is enumerated on its own and its
// number of valid combinations multiplies in. 64 free `_ K` sets cost 64 multiplications.
uint64_t VariantSpace::count() const { return countOver(mSetOptions); }

uint64_t VariantSpace::countOver(const SetOptions& options) const {
    uint64_t total = 1;
    for (size_t set : mFreeSets) {
        if (options[set].empty()) return 0;
        total = saturatingMultiply(total, options[set].size());
    }
    for (const std::vector<size_t>& group : mLinkedGroups) {
        uint64_t valid = 0;
        walk(options, group, [&valid](const VariantKey&) {
            ++valid;
            return true;
        });
        if (valid == 0) return 0;
        total = saturatingMultiply(total, valid);
    }
    return total;
}

void VariantSpace::forEach(const std::function<bool(const VariantKey&)>& visit) const {
    walk(mSetOptions, mAllSets, visit);
}

std::vector<VariantKey> VariantSpace::enumerate() const {
    std::vector<VariantKey> keys;
    keys.reserve(static_cast<size_t>(std::min<uint64_t>(count(), uint64_t{1} << 20)));
    forEach([&keys](const VariantKey& key) {
        keys.push_back(key);
        return true;
    });
    return keys;
}

std::optional<std::vector<size_t>> VariantSpace::optionsOf(const VariantKey& key) const {
    VariantKey rest = key;
    std::vector<size_t> chosen(mSetOptions.size());
    for (size_t set = 0; set < mSetOptions.size(); ++set) {
        VariantKey mask;
        for (const VariantKey& option : mSetOptions[set]) mask = mask | option;
        const VariantKey part = key & mask;
        const std::vector<VariantKey>& options = mSetOptions[set];
        auto found = std::find(options.begin(), options.end(), part);
        if (found == options.end()) return std::nullopt;
        chosen[set] = static_cast<size_t>(found - options.begin());
        rest = rest.andNot(mask);
    }
    if (!rest.empty()) return std::nullopt;
    return chosen;
}

// A rule only reads bits it mentions, so checking every set's rules against the whole key is
// the same as checking them against the prefix that completes them.
bool VariantSpace::contains(const VariantKey& key) const {
    if (!optionsOf(key)) return false;
    for (size_t set = 0; set < mSetOptions.size(); ++set) {
        if (!rulesHold(set, key)) return false;
    }
    return true;
}

uint64_t VariantSpace::countPinned(const std::vector<size_t>& sets,
                                   const std::vector<size_t>& options) const {
    VARC_CHECK(sets.size() == options.size()) << "countPinned: one option per pinned set";
    SetOptions pinned = mSetOptions;
    for (size_t i = 0; i < sets.size(); ++i) {
        VARC_CHECK(options[i] < pinned[sets[i]].size()) << "countPinned: option out of range";
        pinned[sets[i]] = {mSetOptions[sets[i]][options[i]]};
    }
    return countOver(pinned);
}

// The pinned walk's inputs: |pinOfSet[s]| is the position of set s in pins.sets, or kUnpinned.
struct VariantSpace::PinnedWalk {
    const Pins& pins;
    std::vector<size_t> pinOfSet;
    const std::function<bool(const VariantKey&)>& visit;
};

void VariantSpace::forEachPinned(const Pins& pins,
                                 const std::function<bool(const VariantKey&)>& visit) const {
    PinnedWalk walk{pins, std::vector<size_t>(mSetOptions.size(), kUnpinned), visit};
    for (size_t i = 0; i < pins.sets.size(); ++i) walk.pinOfSet[pins.sets[i]] = i;
    for (const std::vector<size_t>& combination : pins.combinations) {
        VARC_CHECK(combination.size() == pins.sets.size()) << "forEachPinned: ragged combination";
        for (size_t i = 0; i < combination.size(); ++i) {
            VARC_CHECK(combination[i] < mSetOptions[pins.sets[i]].size())
                << "forEachPinned: option out of range";
        }
    }
    if (pins.combinations.empty()) return;
    walkPinned(walk, 0, VariantKey{}, 0, pins.combinations.size());
}

// Nested loops as in walk(), written recursively (depth <= 256 sets). combinations[first,
// last) are the ones that agree with the prefix's pinned options; sorted, they form a trie, so
// a pinned set's candidates are the distinct values at its position in that range, ascending
// (= declared order), each owning the sub-range that shares it.
// Example: pins {0, 2} with {(0, 1), (1, 0), (1, 1)}: set 0 tries option 0 with [0, 1) and
// option 1 with [1, 3); under option 1, set 2 tries 0 with [1, 2) and 1 with [2, 3).
bool VariantSpace::walkPinned(const PinnedWalk& walk, size_t set, const VariantKey& prefix,
                              size_t first, size_t last) const {
    if (set == mSetOptions.size()) return walk.visit(prefix);
    auto descend = [&](size_t option, size_t from, size_t to) {
        const VariantKey next = prefix | mSetOptions[set][option];
        return !rulesHold(set, next) || walkPinned(walk, set + 1, next, from, to);
    };
    const size_t pin = walk.pinOfSet[set];
    if (pin == kUnpinned) {
        for (size_t option = 0; option < mSetOptions[set].size(); ++option) {
            if (!descend(option, first, last)) return false;
        }
        return true;
    }
    const std::vector<std::vector<size_t>>& combinations = walk.pins.combinations;
    for (size_t from = first; from < last;) {
        const size_t option = combinations[from][pin];
        size_t to = from;
        while (to < last && combinations[to][pin] == option) ++to;
        if (!descend(option, from, to)) return false;
        from = to;
    }
    return true;
}

}  // namespace varc::variants
