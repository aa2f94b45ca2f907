// SPDX-License-Identifier: Apache-2.0
// CacheChain: the cache levels of a build in order (local first, then shared). A get tries each
// level until one holds a value the caller accepts, and writes a hit from a later level back to
// the earlier ones; a put goes to every writable level. Write-backs are kept and written
// together by flushWriteBacks() (the end of a build, or the chain's destruction), so a local
// folder filled from a shared level gets one bundle instead of thousands of files. A level that fails is skipped for the
// rest of the run and yields one warning (warnings()); the build goes on with the others.
#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "varc/cache/CacheSpec.h"
#include "varc/cache/CacheStorage.h"
#include "varc/core/Result.h"

namespace varc::cache {

class CacheChain {
public:
    explicit CacheChain(std::vector<std::unique_ptr<CacheStorage>> levels);
    ~CacheChain();
    CacheChain(CacheChain&& other) noexcept = default;
    CacheChain& operator=(CacheChain&& other) noexcept;

    // Opens a level per spec (nothing is connected yet: a remote connects on first use).
    static CacheChain open(const std::vector<CacheSpec>& specs);

    // The first value under |key| that |accept| takes; a value it refuses is counted as damaged
    // and the next level is tried. Thread-safe.
    std::optional<std::string> get(std::string_view key,
                                   const std::function<bool(std::string_view)>& accept);

    // get() of many keys at once, level by level, so a remote answers each level's misses in one
    // round trip; |accept| gets the key's index and the value.
    std::vector<std::optional<std::string>> getMany(
        const std::vector<std::string>& keys,
        const std::function<bool(size_t, std::string_view)>& accept);

    // Stores |value| in every writable level; returns the first local write error.
    Status put(std::string_view key, std::string_view value);

    // One message per failed level, naming it and the reason, e.g. "the shared cache
    // redis://127.0.0.1:7000/0 failed (cannot connect: Connection refused); building without it".
    std::vector<std::string> warnings() const;

    std::vector<CacheLevelStats> stats() const;

    // Writes the hits kept for write-back to their levels (one putMany per level) and forgets
    // them. Errors are not returned: a write-back that fails leaves a local miss next time.
    // Thread-safe; called by the build when its lookups are done, and by the destructor.
    void flushWriteBacks();

    const std::vector<std::unique_ptr<CacheStorage>>& levels() const { return mLevels; }

private:
    // Keeps a hit in |level| for the writable levels before it.
    void writeBack(size_t level, std::string_view key, std::string_view value);

    // Kept write-backs are flushed early past this size, so memory stays bounded.
    static constexpr size_t kMaxPendingBytes = size_t{256} << 20;
    struct PendingWriteBacks {
        std::mutex mutex;
        std::vector<std::vector<CacheEntry>> byLevel;  // one list per level
        size_t bytes = 0;
    };

    std::vector<std::unique_ptr<CacheStorage>> mLevels;
    std::unique_ptr<PendingWriteBacks> mPending;
};

}  // namespace varc::cache
