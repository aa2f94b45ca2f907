// SPDX-License-Identifier: Apache-2.0
// DirectoryStorage: a cache level in a local folder, one file per entry at
// <directory>/<first 2 characters of the key>/<key>, and bundles of many entries at
// <directory>/bundles/<16 hex>.bundle (CacheBundle.h; what putMany writes). Every file is
// written atomically (temporary + rename), so concurrent builds can share the folder; nothing is
// flushed to disk (a torn entry is a miss). The bundles' indexes are read once, on the first
// get that finds no entry file: a bundle another process writes later is not seen by this one.
#pragma once

#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include "varc/cache/CacheBundle.h"

#include "varc/cache/CacheStorage.h"

namespace varc::cache {

class DirectoryStorage final : public CacheStorage {
public:
    // Uses |directory| (created on the first put); |name| is for messages.
    DirectoryStorage(std::string directory, std::string name, bool readOnly);

    std::optional<std::string> get(std::string_view key) override;
    Status put(std::string_view key, std::string_view value) override;
    // Few entries go to files of their own; kBundleMinEntries or more go to one bundle.
    Status putMany(const std::vector<CacheEntry>& entries) override;
    Result<CacheUsage> usage() override;
    Result<uint64_t> clear() override;

    // Where the entry for |key| lives.
    std::string pathOf(std::string_view key) const;

    static constexpr size_t kBundleMinEntries = 16;

private:
    struct BundleValue {
        size_t bundle = 0;  // index into mBundlePaths
        uint64_t offset = 0;
        uint32_t length = 0;
    };
    std::string bundleFolder() const { return mDirectory + "/bundles"; }
    // Reads every bundle's index once (under mBundleMutex).
    void loadBundleIndexLocked();
    void indexBundleLocked(const std::string& path, const std::vector<BundleSlot>& slots);
    std::optional<std::string> getFromBundle(std::string_view key);

    std::string mDirectory;
    std::mutex mBundleMutex;
    bool mBundlesLoaded = false;
    std::vector<std::string> mBundlePaths;
    std::unordered_map<std::string, BundleValue> mBundleValues;
};

}  // namespace varc::cache
