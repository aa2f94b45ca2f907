// SPDX-License-Identifier: Apache-2.0
// An open-addressing hash index over a pass's sorted one-word variant keys, built once when a
// pack is opened, so an exact lookup costs one or two probes instead of a binary search's
// log2(n) dependent cache misses (docs/PERFORMANCE.md: 136 ns at 10^5 variants by search).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace varc::reader::detail {

class KeyHashIndex {
public:
    // Passes smaller than this keep the binary search: it stays in a few cache lines.
    static constexpr uint32_t kMinKeys = 64;

    KeyHashIndex() = default;
    // Indexes |count| distinct keys stored as little-endian u64 at |keys|.
    KeyHashIndex(const std::byte* keys, uint32_t count);

    bool empty() const { return mSlots.empty(); }
    // Position of |want| among the keys, or UINT32_MAX. Allocation-free.
    uint32_t find(uint64_t want) const;

private:
    static uint64_t mix(uint64_t key);
    // The key beside its position, so a probe touches one cache line (16 bytes a slot; a pass of
    // 10^5 variants costs 4 MiB of index).
    struct Slot {
        uint64_t key = 0;
        uint32_t positionPlusOne = 0;  // 0 = empty
    };
    std::vector<Slot> mSlots;
    uint64_t mMask = 0;
};

}  // namespace varc::reader::detail
