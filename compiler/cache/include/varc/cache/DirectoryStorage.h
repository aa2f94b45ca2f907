// SPDX-License-Identifier: Apache-2.0
// DirectoryStorage: a cache level in a local folder, one file per entry at
// <directory>/<first 2 characters of the key>/<key>, written atomically (temporary + rename), so
// concurrent builds can share the folder; not flushed to disk (a torn entry is a miss).
#pragma once

#include <string>

#include "varc/cache/CacheStorage.h"

namespace varc::cache {

class DirectoryStorage final : public CacheStorage {
public:
    // Uses |directory| (created on the first put); |name| is for messages.
    DirectoryStorage(std::string directory, std::string name, bool readOnly);

    std::optional<std::string> get(std::string_view key) override;
    Status put(std::string_view key, std::string_view value) override;
    Result<CacheUsage> usage() override;
    Result<uint64_t> clear() override;

    // Where the entry for |key| lives.
    std::string pathOf(std::string_view key) const;

private:
    std::string mDirectory;
};

}  // namespace varc::cache
