// SPDX-License-Identifier: Apache-2.0
// CacheChain::open: one storage per spec.
#include "varc/cache/CacheChain.h"
#include "varc/cache/DirectoryStorage.h"
#include "varc/cache/RedisStorage.h"

namespace varc::cache {

CacheChain CacheChain::open(const std::vector<CacheSpec>& specs) {
    std::vector<std::unique_ptr<CacheStorage>> levels;
    for (const CacheSpec& spec : specs) {
        if (spec.kind == CacheSpec::Kind::Directory) {
            levels.push_back(
                std::make_unique<DirectoryStorage>(spec.directory, spec.url, spec.readOnly));
        } else {
            levels.push_back(std::make_unique<RedisStorage>(spec));
        }
    }
    return CacheChain(std::move(levels));
}

}  // namespace varc::cache
