// SPDX-License-Identifier: Apache-2.0
// Scans of registered files, kept so each file is scanned once per IncludeResolver.
#pragma once

#include <memory>
#include <unordered_map>

#include "ScannedFile.h"
#include "varc/includes/SourceMap.h"

namespace varc::includes {

class ScanCache {
public:
    // The scan of |id|'s contents in |sourceMap|, made on first use. The reference stays valid
    // for the cache's lifetime; |sourceMap| must outlive the cache and keep |id|'s contents.
    const ScannedFile& get(const SourceMap& sourceMap, FileId id);

private:
    std::unordered_map<FileId, std::unique_ptr<ScannedFile>> mScans;
};

}  // namespace varc::includes
