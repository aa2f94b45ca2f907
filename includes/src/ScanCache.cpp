// SPDX-License-Identifier: Apache-2.0
// Scans of registered files, kept so each file is scanned once per IncludeResolver.
#include "ScanCache.h"

#include "LineScanner.h"

namespace varc::includes {

const ScannedFile& ScanCache::get(const SourceMap& sourceMap, FileId id) {
    std::unique_ptr<ScannedFile>& slot = mScans[id];
    if (!slot) slot = std::make_unique<ScannedFile>(LineScanner::scan(sourceMap.contents(id)));
    return *slot;
}

}  // namespace varc::includes
