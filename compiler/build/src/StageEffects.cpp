// SPDX-License-Identifier: Apache-2.0
// Which keyword sets turned out to change which stage's program (derived, not declared).
#include "varc/build/StageEffects.h"

#include <unordered_map>

namespace varc::compiler {

namespace {

// All bits any option of |options| sets: clearing them removes the set's choice from a key.
variants::VariantKey unionOf(const std::vector<variants::VariantKey>& options) {
    variants::VariantKey all;
    for (const variants::VariantKey& option : options) all = all | option;
    return all;
}

// Variants that agree on every other set fall into one group; the set affects a stage when a
// group holds two different programs for it.
uint32_t effectOfSet(const variants::VariantKey& setBits,
                     const std::vector<CompiledVariant>& variants) {
    std::unordered_map<variants::VariantKey, const CompiledVariant*> firstInGroup;
    uint32_t stages = 0;
    for (const CompiledVariant& variant : variants) {
        auto [it, inserted] = firstInGroup.emplace(variant.key.andNot(setBits), &variant);
        if (inserted) continue;
        for (size_t slot = 0; slot < kStageCount; ++slot) {
            if (it->second->programs[slot] != variant.programs[slot]) stages |= stageBitOfSlot(slot);
        }
    }
    return stages;
}

}  // namespace

std::vector<uint32_t> computeSetStageEffects(const variants::VariantSpace& space,
                                             const std::vector<CompiledVariant>& variants) {
    std::vector<uint32_t> effects;
    for (const std::vector<variants::VariantKey>& options : space.setOptions()) {
        effects.push_back(effectOfSet(unionOf(options), variants));
    }
    return effects;
}

}  // namespace varc::compiler
