// SPDX-License-Identifier: Apache-2.0
// Finds the file an #include names: including file's directory, -I dirs, built-in dir.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "varc/includes/FileSystem.h"
#include "varc/includes/IncludeResolver.h"
#include "varc/includes/SourceMap.h"

namespace varc::includes {

class IncludeLocator {
public:
    // All three are borrowed and must outlive the locator.
    IncludeLocator(const FileSystem& fileSystem, const SourceMap& sourceMap,
                   const IncludeOptions& options)
        : mFileSystem(fileSystem), mSourceMap(sourceMap), mOptions(options) {}

    // Returns the normalised path of |name| (as written; '\\' is read as '/') searched in
    // |includerDir|, then each -I dir, then the built-in dir; a registered file counts as
    // existing. A name written from a Unity project's root ("Assets/...", "Packages/...") is
    // then searched from the project root (IncludeOptions::projectRoot, or else each ancestor of
    // |includerDir|). Last, as on the case-insensitive file systems Unity projects are made on,
    // the same folders are searched for a file whose name differs only in ASCII case; then
    // |*caseDiffers| is set (when given). On failure returns nullopt and fills |searched| with
    // the directories tried, in order, without duplicates ("." for the current directory; empty
    // for absolute names).
    // Example: locate("My Lighting.cginc", "shaders", searched) -> "shaders/My Lighting.cginc".
    std::optional<std::string> locate(const std::string& name, const std::string& includerDir,
                                      std::vector<std::string>& searched,
                                      bool* caseDiffers = nullptr) const;

private:
    bool exists(const std::string& path) const;
    std::optional<std::string> findFromProjectRoot(const std::string& name,
                                                   const std::string& includerDir,
                                                   std::vector<std::string>& searched) const;
    std::optional<std::string> findIgnoringCase(const std::string& dir,
                                                const std::string& name) const;

    const FileSystem& mFileSystem;
    const SourceMap& mSourceMap;
    const IncludeOptions& mOptions;
};

}  // namespace varc::includes
