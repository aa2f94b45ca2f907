// SPDX-License-Identifier: Apache-2.0
// Which keyword sets turned out to change which stage's program (derived, not declared).
#include "varc/driver/StageEffects.h"

#include <unordered_map>

namespace varc::driver {

namespace {

// All bits any option of |options| sets: clearing them removes the set's choice from a key.
variants::VariantKey unionOf(const std::vector<variants::VariantKey>& options) {
    variants::VariantKey all;
    for (const variants::VariantKey& option : options) all = all | option;
    return all;
}

// Variants that agree on every other set fall into one group; the set affects a stage when a
// group holds two different programs for it.
StageMask effectOfSet(const variants::VariantKey& setBits,
                      const std::vector<pack::PackVariant>& variants) {
    std::unordered_map<variants::VariantKey, const pack::PackVariant*> firstInGroup;
    StageMask stages = 0;
    for (const pack::PackVariant& variant : variants) {
        auto [it, inserted] = firstInGroup.emplace(variant.key.andNot(setBits), &variant);
        if (inserted) continue;
        for (Stage stage : kStages) {
            size_t slot = stageIndex(stage);
            if (it->second->programs[slot] != variant.programs[slot]) stages |= stageBit(stage);
        }
    }
    return stages;
}

}  // namespace

std::vector<StageMask> computeSetStageEffects(const variants::VariantSpace& space,
                                              const std::vector<pack::PackVariant>& variants) {
    std::vector<StageMask> effects;
    for (const std::vector<variants::VariantKey>& options : space.setOptions()) {
        effects.push_back(effectOfSet(unionOf(options), variants));
    }
    return effects;
}

}  // namespace varc::driver
