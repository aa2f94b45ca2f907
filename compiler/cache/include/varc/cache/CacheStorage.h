// SPDX-License-Identifier: Apache-2.0
// CacheStorage: one level of the program cache (a local folder, a Redis server): byte values by
// name, with the counters the build summary reports.
//
// Every call is thread-safe (compile workers share one storage). A storage never throws and never
// fails a build: a remote that cannot be reached, answers too slowly or answers nonsense marks
// itself failed() for the rest of the run, remembers why (failure()), and from then on every get
// is a miss and every put is skipped. Values are opaque here; whoever reads them checks them
// (ProgramCache checksums every entry), and a damaged value is reported with countDamaged().
#pragma once

#include <atomic>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "varc/cache/CacheBundle.h"
#include "varc/core/Result.h"

namespace varc::cache {

// A snapshot of one level's counters.
struct CacheLevelStats {
    std::string name;  // the level's URL, for messages
    uint64_t hits = 0, misses = 0, damaged = 0, writes = 0;
    uint64_t bytesRead = 0, bytesWritten = 0;
    uint64_t errors = 0, timeouts = 0;  // failed operations (timeouts are not also errors)
    bool failed = false;                // given up on for the rest of the run
};

// What a level holds, for `varc cache stats`.
struct CacheUsage {
    uint64_t entries = 0;
    uint64_t bytes = 0;
};

class CacheStorage {
public:
    explicit CacheStorage(std::string name, bool readOnly)
        : mName(std::move(name)), mReadOnly(readOnly) {}
    virtual ~CacheStorage() = default;
    CacheStorage(const CacheStorage&) = delete;
    CacheStorage& operator=(const CacheStorage&) = delete;

    // The value stored under |key| (e.g. "0123...ef.program"), or nullopt for a miss, a read
    // error or a failed level. Counts bytes read; hits and misses are counted by the caller, who
    // alone knows whether the value is sound.
    virtual std::optional<std::string> get(std::string_view key) = 0;

    // get() of every key, in order; a remote answers them in one round trip (pipelined).
    virtual std::vector<std::optional<std::string>> getMany(const std::vector<std::string>& keys);

    // Stores |value| under |key| (nothing on a read-only or failed level). A local level's write
    // error is returned (the caller warns that the cache is not updated); a remote's is counted,
    // noted in failure() and not returned.
    virtual Status put(std::string_view key, std::string_view value) = 0;

    // put() of every entry; a local folder writes many in one file. Returns the first error.
    virtual Status putMany(const std::vector<CacheEntry>& entries);

    // How many entries and bytes the level holds; an error names the level and the reason.
    virtual Result<CacheUsage> usage() = 0;

    // Removes every entry varc stored (and nothing else); returns how many.
    virtual Result<uint64_t> clear() = 0;

    const std::string& name() const { return mName; }
    bool readOnly() const { return mReadOnly; }
    bool failed() const { return mFailed.load(); }
    // Why the level failed or refused writes ("" if it did not): the one warning to print.
    std::string failure() const;

    void countHit() { ++mHits; }
    void countMiss() { ++mMisses; }
    void countDamaged() { ++mDamaged; }
    CacheLevelStats stats() const;

protected:
    void countRead(size_t bytes) { mBytesRead += bytes; }
    void countWrite(size_t bytes) {
        ++mWrites;
        mBytesWritten += bytes;
    }
    // Counts an error (or a timeout) and keeps the first |reason|; |fatal| gives the level up.
    void noteError(const std::string& reason, bool timeout, bool fatal);

private:
    std::string mName;
    bool mReadOnly = false;
    std::atomic<bool> mFailed{false};
    std::atomic<uint64_t> mHits{0}, mMisses{0}, mDamaged{0}, mWrites{0};
    std::atomic<uint64_t> mBytesRead{0}, mBytesWritten{0}, mErrors{0}, mTimeouts{0};
    mutable std::mutex mFailureMutex;
    std::string mFailure;
};

}  // namespace varc::cache
