// SPDX-License-Identifier: Apache-2.0
#include "varc/cache/CacheChain.h"

namespace varc::cache {

CacheChain::CacheChain(std::vector<std::unique_ptr<CacheStorage>> levels)
    : mLevels(std::move(levels)) {}

std::optional<std::string> CacheChain::get(std::string_view key,
                                           const std::function<bool(std::string_view)>& accept) {
    for (size_t i = 0; i < mLevels.size(); ++i) {
        CacheStorage& level = *mLevels[i];
        if (level.failed()) continue;
        std::optional<std::string> value = level.get(key);
        if (value && !accept(*value)) {
            level.countDamaged();
            value.reset();
        }
        if (!value) {
            level.countMiss();
            continue;
        }
        level.countHit();
        // A hit in a shared level fills the local ones, so the next build finds it locally.
        for (size_t j = 0; j < i; ++j) {
            if (!mLevels[j]->readOnly() && !mLevels[j]->failed()) (void)mLevels[j]->put(key, *value);
        }
        return value;
    }
    return std::nullopt;
}

Status CacheChain::put(std::string_view key, std::string_view value) {
    Status first = Ok{};
    for (const auto& level : mLevels) {
        if (level->readOnly() || level->failed()) continue;
        Status stored = level->put(key, value);
        if (!stored && first) first = std::move(stored);
    }
    return first;
}

std::vector<std::string> CacheChain::warnings() const {
    std::vector<std::string> messages;
    for (const auto& level : mLevels) {
        std::string failure = level->failure();
        if (failure.empty()) continue;
        messages.push_back("the cache " + level->name() + " " +
                           (level->failed() ? "failed (" + failure + "); building without it"
                                            : "refused writes (" + failure +
                                                  "); not written for the rest of this build"));
    }
    return messages;
}

std::vector<CacheLevelStats> CacheChain::stats() const {
    std::vector<CacheLevelStats> stats;
    for (const auto& level : mLevels) stats.push_back(level->stats());
    return stats;
}

}  // namespace varc::cache
