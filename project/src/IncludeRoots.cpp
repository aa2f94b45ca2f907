// SPDX-License-Identifier: Apache-2.0
// Resolving `Assets/...` and `Packages/<name>/...` include paths to files on disk.
#include "varc/project/IncludeRoots.h"

namespace varc::project {

namespace fs = std::filesystem;

namespace {

std::optional<fs::path> firstExisting(const std::vector<fs::path>& folders, std::string_view rest) {
    for (const fs::path& folder : folders) {
        fs::path candidate = folder / fs::path(std::string(rest));
        std::error_code error;
        if (fs::is_regular_file(candidate, error)) return candidate;
    }
    return std::nullopt;
}

}  // namespace

std::optional<fs::path> IncludeRoots::resolve(std::string_view includePath) const {
    if (includePath.rfind("Assets/", 0) == 0) return firstExisting(projectRoots, includePath);
    if (includePath.rfind("Packages/", 0) != 0) return std::nullopt;
    size_t nameEnd = includePath.find('/', 9);
    if (nameEnd == std::string_view::npos) return std::nullopt;
    auto found = packages.find(std::string(includePath.substr(0, nameEnd)));
    if (found == packages.end()) return std::nullopt;
    return firstExisting(found->second, includePath.substr(nameEnd + 1));
}

}  // namespace varc::project
