// SPDX-License-Identifier: Apache-2.0
// Variant-independent text rewrites, computed once per text.
#include "jobs/TextRewriteMemo.h"

#include <xxhash.h>

namespace varc::driver::detail {

const std::string& TextRewriteMemo::apply(std::string_view name, const std::string& text,
                                          const Rewrite& rewrite) {
    XXH128_hash_t hash = XXH3_128bits(text.data(), text.size());
    Key key{std::string(name), hash.low64, hash.high64, text.size()};
    // The rewrite runs under the lock: a thread that wants the same result would wait for it
    // anyway, and a pass has only a few distinct rewrites.
    std::lock_guard<std::mutex> lock(mMutex);
    auto [it, inserted] = mResults.try_emplace(std::move(key));
    if (inserted) it->second = std::make_unique<const std::string>(rewrite(text));
    return *it->second;
}

}  // namespace varc::driver::detail
