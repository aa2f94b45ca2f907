// SPDX-License-Identifier: Apache-2.0
// Splices #include files into a program block, with guards, cycle checks and #line mapping.
#include "varc/includes/IncludeResolver.h"

#include "Expansion.h"
#include "ScanCache.h"

namespace varc::includes {

IncludeResolver::IncludeResolver(const FileSystem& fileSystem, SourceMap& sourceMap,
                                 IncludeOptions options)
    : mFileSystem(fileSystem),
      mSourceMap(sourceMap),
      mOptions(std::move(options)),
      mScanCache(std::make_unique<ScanCache>()) {}

IncludeResolver::~IncludeResolver() = default;
IncludeResolver::IncludeResolver(IncludeResolver&&) noexcept = default;

std::optional<ExpandedSource> IncludeResolver::expand(const std::vector<SourceText>& roots,
                                                      DiagnosticSink& sink) {
    Expansion expansion(mFileSystem, mSourceMap, mOptions, *mScanCache, sink);
    return expansion.run(roots);
}

}  // namespace varc::includes
