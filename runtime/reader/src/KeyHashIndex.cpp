// SPDX-License-Identifier: Apache-2.0
#include "KeyHashIndex.h"

#include <bit>

#include "varc/pack/LittleEndian.h"

namespace varc::reader::detail {

// A 64-bit finaliser (from MurmurHash3's fmix64): keys are bit sets with few bits, so they need
// real mixing before masking.
uint64_t KeyHashIndex::mix(uint64_t key) {
    key ^= key >> 33;
    key *= 0xff51afd7ed558ccdULL;
    key ^= key >> 33;
    key *= 0xc4ceb9fe1a85ec53ULL;
    key ^= key >> 33;
    return key;
}

KeyHashIndex::KeyHashIndex(const std::byte* keys, uint32_t count) {
    uint64_t size = std::bit_ceil(uint64_t{count} * 2);  // load factor <= 1/2
    mSlots.assign(size, Slot{});
    mMask = size - 1;
    for (uint32_t i = 0; i < count; ++i) {
        uint64_t key = pack::loadU64(keys + 8 * size_t{i});
        uint64_t slot = mix(key) & mMask;
        while (mSlots[slot].positionPlusOne != 0) slot = (slot + 1) & mMask;
        mSlots[slot] = {key, i + 1};
    }
}

uint32_t KeyHashIndex::find(uint64_t want) const {
    for (uint64_t slot = mix(want) & mMask;; slot = (slot + 1) & mMask) {
        const Slot& entry = mSlots[slot];
        if (entry.positionPlusOne == 0) return UINT32_MAX;
        if (entry.key == want) return entry.positionPlusOne - 1;
    }
}

}  // namespace varc::reader::detail
