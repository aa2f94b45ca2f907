// SPDX-License-Identifier: Apache-2.0
// VariantSpace: counting by independent groups, and the pruned odometer that enumerates.
#include "varc/variants/VariantSpace.h"

#include <algorithm>

#include "VariantSpaceBuilder.h"
#include "varc/core/SaturatingMath.h"

namespace varc::variants {

namespace {

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
bool VariantSpace::walk(const std::vector<size_t>& sets,
                        const std::function<bool(const VariantKey&)>& visit) const {
    if (sets.empty()) return visit(VariantKey{});
    for (size_t set : sets) {
        if (mSetOptions[set].empty()) return true;
    }
    const size_t n = sets.size();
    std::vector<size_t> choice(n, 0);
    std::vector<VariantKey> prefix(n + 1);
    size_t depth = 0;
    while (true) {
        const std::vector<VariantKey>& options = mSetOptions[sets[depth]];
        prefix[depth + 1] = prefix[depth] | options[choice[depth]];
        if (rulesHold(sets[depth], prefix[depth + 1])) {
            if (depth + 1 < n) {
                choice[++depth] = 0;
                continue;
            }
            if (!visit(prefix[n])) return false;
        }
        while (++choice[depth] == mSetOptions[sets[depth]].size()) {
            if (depth == 0) return true;
            --depth;
        }
    }
}

// Sets that no rule links multiply; each rule-linked group is enumerated on its own and its
// number of valid combinations multiplies in. 64 free `_ K` sets cost 64 multiplications.
uint64_t VariantSpace::count() const {
    uint64_t total = 1;
    for (size_t set : mFreeSets) {
        if (mSetOptions[set].empty()) return 0;
        total = saturatingMultiply(total, mSetOptions[set].size());
    }
    for (const std::vector<size_t>& group : mLinkedGroups) {
        uint64_t valid = 0;
        walk(group, [&valid](const VariantKey&) {
            ++valid;
            return true;
        });
        if (valid == 0) return 0;
        total = saturatingMultiply(total, valid);
    }
    return total;
}

void VariantSpace::forEach(const std::function<bool(const VariantKey&)>& visit) const {
    walk(mAllSets, visit);
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

}  // namespace varc::variants
