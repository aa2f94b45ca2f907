// SPDX-License-Identifier: Apache-2.0
// An even sample of a pass's variants (VariantSample.h).
#include "varc/variants/VariantSample.h"

namespace varc::variants {

std::vector<VariantKey> sampleEvenly(std::vector<VariantKey> keys, uint64_t count) {
    const uint64_t n = keys.size();
    if (count == 0 || count >= n) return keys;
    std::vector<VariantKey> sample;
    sample.reserve(count);
    if (count == 1) {
        sample.push_back(std::move(keys.front()));
        return sample;
    }
    // floor(i * (n - 1) / (count - 1)) split as i * q + floor(i * r / (count - 1)), so that no
    // product exceeds (count - 1)^2, far below 2^64 for any vector that fits in memory.
    const uint64_t q = (n - 1) / (count - 1), r = (n - 1) % (count - 1);
    for (uint64_t i = 0; i < count; ++i)
        sample.push_back(std::move(keys[i * q + i * r / (count - 1)]));
    return sample;
}

}  // namespace varc::variants
