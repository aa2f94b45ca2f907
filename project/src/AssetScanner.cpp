// SPDX-License-Identifier: Apache-2.0
// The directory walk behind loadProject: Unity's ignore rules, overlays, `.meta` GUIDs.
#include "AssetScanner.h"

#include <algorithm>
#include <map>

#include "varc/core/AsciiCase.h"
#include "varc/core/Trim.h"

namespace varc::project {

namespace fs = std::filesystem;

namespace {

bool endsWith(const std::string& text, std::string_view suffix) {
    return text.size() >= suffix.size() &&
           text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string stripSuffix(const std::string& text, std::string_view suffix) {
    return text.substr(0, text.size() - suffix.size());
}

std::string assetPathOf(const AssetArea& area, const fs::path& relative) {
    std::string inner = relative.generic_string();
    return area.assetPrefix.empty() ? inner : area.assetPrefix + "/" + inner;
}

// Calls |visit|(relative path, file) for each regular file under |folder|.
template <typename Visit>
void walk(const fs::path& folder, bool includeIgnored, LoadContext& context, Visit visit) {
    std::error_code error;
    if (!fs::is_directory(folder, error)) return;
    fs::recursive_directory_iterator it(folder, fs::directory_options::skip_permission_denied,
                                        error);
    for (; !error && it != fs::recursive_directory_iterator(); it.increment(error)) {
        const fs::directory_entry& entry = *it;
        std::string name = entry.path().filename().string();
        std::error_code typeError;
        if (!includeIgnored && isUnityIgnoredName(name)) {
            if (entry.is_directory(typeError)) it.disable_recursion_pending();
            continue;
        }
        if (entry.is_regular_file(typeError))
            visit(entry.path().lexically_relative(folder), entry.path());
    }
    if (error) context.warn(folder, "cannot list the folder completely: " + error.message());
}

void sortByPath(std::vector<ScannedFile>& files) {
    std::sort(files.begin(), files.end(), [](const ScannedFile& a, const ScannedFile& b) {
        return a.assetPath != b.assetPath ? a.assetPath < b.assetPath : a.file < b.file;
    });
}

}  // namespace

bool isUnityIgnoredName(const std::string& name) {
    if (name.empty()) return false;
    std::string lower = toAsciiLower(name);
    return name.front() == '.' || name.back() == '~' || lower == "cvs" || endsWith(lower, ".tmp");
}

AssetFiles scanAssets(const std::vector<AssetArea>& areas, bool includeIgnored,
                      LoadContext& context) {
    AssetFiles files;
    std::map<std::string, fs::path> shaders;  // asset path -> file; the first found wins
    for (const AssetArea& area : areas) {
        walk(area.folder, includeIgnored, context,
             [&](const fs::path& relative, const fs::path& file) {
                 std::string assetPath = assetPathOf(area, relative);
                 std::string lower = toAsciiLower(assetPath);
                 if (endsWith(lower, ".shader")) {
                     shaders.emplace(assetPath, file);
                 } else if (endsWith(lower, ".shader.meta")) {
                     files.shaderMetas.push_back({stripSuffix(assetPath, ".meta"), file});
                 } else if (endsWith(lower, ".mat")) {
                     files.materials.push_back({assetPath, file});
                 } else if (endsWith(lower, ".shadervariants")) {
                     files.collections.push_back({assetPath, file});
                 } else if (endsWith(lower, ".shadervariants.meta")) {
                     files.collectionMetas.push_back({stripSuffix(assetPath, ".meta"), file});
                 }
             });
        for (const fs::path& overlay : area.overlayFolders) {
            walk(overlay, includeIgnored, context,
                 [&](const fs::path& relative, const fs::path& file) {
                     std::string assetPath = assetPathOf(area, relative);
                     if (endsWith(toAsciiLower(assetPath), ".shader"))
                         shaders.emplace(assetPath, file);
                 });
        }
    }
    for (auto& [assetPath, file] : shaders) files.shaders.push_back({assetPath, file});
    for (auto* list :
         {&files.shaderMetas, &files.materials, &files.collections, &files.collectionMetas}) {
        sortByPath(*list);
    }
    return files;
}

std::string readMetaGuid(const fs::path& metaFile, LoadContext& context) {
    auto text = context.readText(metaFile);
    if (!text) return {};
    std::string_view rest = *text;
    uint32_t lineNumber = 0;
    while (!rest.empty()) {
        size_t end = rest.find('\n');
        std::string_view line = rest.substr(0, end);
        rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
        ++lineNumber;
        if (line.substr(0, 5) != "guid:") continue;
        std::string_view guid = trim(line.substr(5));
        if (!guid.empty()) return std::string(guid);
        context.warn(metaFile, lineNumber, 1, "empty guid: line");
        return {};
    }
    context.warn(metaFile, "no guid: line; the asset cannot be referenced by GUID");
    return {};
}

}  // namespace varc::project
