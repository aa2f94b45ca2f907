// SPDX-License-Identifier: Apache-2.0
// Picks the variant to use for a requested keyword set: exact, closest, first or strict.
#include "varc/variants/VariantSelector.h"

#include <array>

namespace varc::variants {

namespace {

// How well a variant V fits the request R (docs/KEYWORDS.md §8): more shared keywords is
// better, then fewer extra keywords, then earlier in enumeration order.
struct Score {
    size_t shared = 0;
    size_t extra = 0;
    size_t index = 0;

    bool betterThan(const Score& other) const {
        if (shared != other.shared) return shared > other.shared;
        if (extra != other.extra) return extra < other.extra;
        return index < other.index;
    }
};

Score scoreOf(const VariantKey& variant, const VariantKey& requested, size_t index) {
    return {(variant & requested).count(), variant.andNot(requested).count(), index};
}

constexpr size_t kNearestCount = 3;

// The kNearestCount best variants, best first, in a fixed array (no allocation until the end).
std::vector<size_t> nearestVariants(std::span<const VariantKey> available,
                                    const VariantKey& requested) {
    std::array<Score, kNearestCount> best{};
    size_t kept = 0;
    for (size_t i = 0; i < available.size(); ++i) {
        Score score = scoreOf(available[i], requested, i);
        if (kept == kNearestCount && !score.betterThan(best[kept - 1])) continue;
        size_t slot = kept < kNearestCount ? kept++ : kNearestCount - 1;
        while (slot > 0 && score.betterThan(best[slot - 1])) {
            best[slot] = best[slot - 1];
            --slot;
        }
        best[slot] = score;
    }
    std::vector<size_t> indices;
    for (size_t i = 0; i < kept; ++i) indices.push_back(best[i].index);
    return indices;
}

std::optional<size_t> closestVariant(std::span<const VariantKey> available,
                                     const VariantKey& requested) {
    if (available.empty()) return std::nullopt;
    Score best = scoreOf(available[0], requested, 0);
    for (size_t i = 1; i < available.size(); ++i) {
        Score score = scoreOf(available[i], requested, i);
        if (score.betterThan(best)) best = score;
    }
    return best.index;
}

}  // namespace

std::optional<SelectionPolicy> parseSelectionPolicy(std::string_view name) {
    if (name == "exact") return SelectionPolicy::Exact;
    if (name == "closest") return SelectionPolicy::Closest;
    if (name == "first") return SelectionPolicy::First;
    if (name == "strict") return SelectionPolicy::Strict;
    return std::nullopt;
}

const char* toString(SelectionPolicy policy) {
    switch (policy) {
        case SelectionPolicy::Exact:
            return "exact";
        case SelectionPolicy::Closest:
            return "closest";
        case SelectionPolicy::First:
            return "first";
        case SelectionPolicy::Strict:
            return "strict";
    }
    return "closest";
}

Selection selectVariant(std::span<const VariantKey> available, const VariantKey& requested,
                        SelectionPolicy policy) {
    Selection selection;
    for (size_t i = 0; i < available.size(); ++i) {
        if (available[i] == requested) {
            selection.index = i;
            selection.exact = true;
            return selection;
        }
    }
    switch (policy) {
        case SelectionPolicy::Closest:
            selection.index = closestVariant(available, requested);
            break;
        case SelectionPolicy::First:
            if (!available.empty()) selection.index = 0;
            break;
        case SelectionPolicy::Exact:
        case SelectionPolicy::Strict:
            selection.nearest = nearestVariants(available, requested);
            break;
    }
    return selection;
}

}  // namespace varc::variants
