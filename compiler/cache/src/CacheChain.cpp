// SPDX-License-Identifier: Apache-2.0
#include "varc/cache/CacheChain.h"

namespace varc::cache {

CacheChain::CacheChain(std::vector<std::unique_ptr<CacheStorage>> levels)
    : mLevels(std::move(levels)), mPending(std::make_unique<PendingWriteBacks>()) {
    mPending->byLevel.resize(mLevels.size());
}

CacheChain::~CacheChain() { flushWriteBacks(); }

CacheChain& CacheChain::operator=(CacheChain&& other) noexcept {
    if (this != &other) {
        flushWriteBacks();
        mLevels = std::move(other.mLevels);
        mPending = std::move(other.mPending);
    }
    return *this;
}

std::optional<std::string> CacheChain::get(std::string_view key,
                                           const std::function<bool(std::string_view)>& accept) {
    return getMany({std::string(key)},
                   [&](size_t, std::string_view value) { return accept(value); })[0];
}

std::vector<std::optional<std::string>> CacheChain::getMany(
    const std::vector<std::string>& keys,
    const std::function<bool(size_t, std::string_view)>& accept) {
    std::vector<std::optional<std::string>> found(keys.size());
    std::vector<size_t> pending(keys.size());
    for (size_t k = 0; k < keys.size(); ++k) pending[k] = k;
    for (size_t i = 0; i < mLevels.size() && !pending.empty(); ++i) {
        CacheStorage& level = *mLevels[i];
        if (level.failed()) continue;
        std::vector<std::string> asked;
        for (size_t k : pending) asked.push_back(keys[k]);
        std::vector<std::optional<std::string>> values = level.getMany(asked);
        std::vector<size_t> missed;
        for (size_t n = 0; n < pending.size(); ++n) {
            std::optional<std::string>& value = values[n];
            if (value && !accept(pending[n], *value)) {
                level.countDamaged();
                value.reset();
            }
            if (!value) {
                level.countMiss();
                missed.push_back(pending[n]);
                continue;
            }
            level.countHit();
            writeBack(i, keys[pending[n]], *value);
            found[pending[n]] = std::move(value);
        }
        pending = std::move(missed);
    }
    return found;
}

void CacheChain::writeBack(size_t level, std::string_view key, std::string_view value) {
    // A hit in a shared level fills the local ones, so the next build finds it locally.
    bool full = false;
    {
        std::lock_guard<std::mutex> lock(mPending->mutex);
        for (size_t j = 0; j < level; ++j) {
            if (mLevels[j]->readOnly() || mLevels[j]->failed()) continue;
            mPending->byLevel[j].push_back({std::string(key), std::string(value)});
            mPending->bytes += key.size() + value.size();
        }
        full = mPending->bytes > kMaxPendingBytes;
    }
    if (full) flushWriteBacks();
}

void CacheChain::flushWriteBacks() {
    if (!mPending) return;  // moved from
    std::vector<std::vector<CacheEntry>> byLevel(mLevels.size());
    {
        std::lock_guard<std::mutex> lock(mPending->mutex);
        std::swap(byLevel, mPending->byLevel);
        mPending->byLevel.resize(mLevels.size());
        mPending->bytes = 0;
    }
    for (size_t j = 0; j < byLevel.size(); ++j) {
        if (!byLevel[j].empty() && !mLevels[j]->failed()) (void)mLevels[j]->putMany(byLevel[j]);
    }
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
