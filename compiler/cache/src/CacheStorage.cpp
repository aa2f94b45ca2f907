// SPDX-License-Identifier: Apache-2.0
#include "varc/cache/CacheStorage.h"

namespace varc::cache {

std::vector<std::optional<std::string>> CacheStorage::getMany(
    const std::vector<std::string>& keys) {
    std::vector<std::optional<std::string>> values;
    values.reserve(keys.size());
    for (const std::string& key : keys) values.push_back(get(key));
    return values;
}

Status CacheStorage::putMany(const std::vector<CacheEntry>& entries) {
    Status first = Ok{};
    for (const CacheEntry& entry : entries) {
        Status stored = put(entry.key, entry.value);
        if (!stored && first) first = std::move(stored);
    }
    return first;
}

std::string CacheStorage::failure() const {
    std::lock_guard<std::mutex> lock(mFailureMutex);
    return mFailure;
}

CacheLevelStats CacheStorage::stats() const {
    CacheLevelStats stats;
    stats.name = mName;
    stats.hits = mHits;
    stats.misses = mMisses;
    stats.damaged = mDamaged;
    stats.writes = mWrites;
    stats.bytesRead = mBytesRead;
    stats.bytesWritten = mBytesWritten;
    stats.errors = mErrors;
    stats.timeouts = mTimeouts;
    stats.failed = mFailed;
    return stats;
}

void CacheStorage::noteError(const std::string& reason, bool timeout, bool fatal) {
    ++(timeout ? mTimeouts : mErrors);
    if (fatal) mFailed = true;
    std::lock_guard<std::mutex> lock(mFailureMutex);
    if (mFailure.empty()) mFailure = reason;
}

}  // namespace varc::cache
