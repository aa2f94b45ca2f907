// SPDX-License-Identifier: Apache-2.0
// An even sample of a pass's variants, for `varc build --sample-variants N` (a quick check that
// every pass compiles across its keyword space, not a pack to ship).
#pragma once

#include <cstdint>
#include <vector>

#include "varc/variants/VariantKey.h"

namespace varc::variants {

// At most |count| of |keys|, spread evenly over their order and kept in it: with
// n = keys.size() > count >= 2, the elements at floor(i * (n - 1) / (count - 1)) for
// i in [0, count), so the first and the last are always in; count 1 keeps the first.
// count 0 or count >= n returns |keys| unchanged.
std::vector<VariantKey> sampleEvenly(std::vector<VariantKey> keys, uint64_t count);

}  // namespace varc::variants
