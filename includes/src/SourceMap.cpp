// SPDX-License-Identifier: Apache-2.0
// Registry of source files: FileId <-> path and contents, with a line index for lineText.
#include "varc/includes/SourceMap.h"

#include "varc/core/Check.h"
#include "varc/includes/FileSystem.h"

namespace varc::includes {

namespace {

// Offsets where lines start. "a\nb\n" has two lines (0, 2); a final line without '\n' counts.
std::vector<size_t> indexLines(const std::string& contents) {
    std::vector<size_t> starts;
    if (contents.empty()) return starts;
    starts.push_back(0);
    for (size_t i = 0; i + 1 < contents.size(); ++i) {
        if (contents[i] == '\n') starts.push_back(i + 1);
    }
    return starts;
}

}  // namespace

FileId SourceMap::addFile(const std::string& path, std::string contents) {
    std::string key = normalizePath(path);
    if (auto existing = mByPath.find(key); existing != mByPath.end()) return existing->second;
    VARC_CHECK(mFiles.size() < kNoFile) << "too many source files";
    auto id = static_cast<FileId>(mFiles.size());
    std::vector<size_t> lineStarts = indexLines(contents);
    mFiles.push_back({key, std::move(contents), std::move(lineStarts)});
    mByPath.emplace(std::move(key), id);
    return id;
}

std::optional<FileId> SourceMap::find(const std::string& path) const {
    auto it = mByPath.find(normalizePath(path));
    if (it == mByPath.end()) return std::nullopt;
    return it->second;
}

const std::string& SourceMap::path(FileId id) const {
    VARC_CHECK(id < mFiles.size()) << "unknown FileId " << id;
    return mFiles[id].path;
}

const std::string& SourceMap::contents(FileId id) const {
    VARC_CHECK(id < mFiles.size()) << "unknown FileId " << id;
    return mFiles[id].contents;
}

std::string SourceMap::lineText(FileId id, uint32_t line) const {
    if (id >= mFiles.size() || line == 0) return "";
    const File& file = mFiles[id];
    if (line > file.lineStarts.size()) return "";
    size_t begin = file.lineStarts[line - 1];
    size_t end = line < file.lineStarts.size() ? file.lineStarts[line] - 1 : file.contents.size();
    if (end > begin && file.contents[end - 1] == '\n') --end;
    if (end > begin && file.contents[end - 1] == '\r') --end;
    return file.contents.substr(begin, end - begin);
}

std::string SourceMap::format(SourceLocation location) const {
    if (location.file == kNoFile || location.file >= mFiles.size()) return "<unknown>";
    std::string text = mFiles[location.file].path;
    if (location.line == 0) return text;
    text += ":" + std::to_string(location.line);
    if (location.column != 0) text += ":" + std::to_string(location.column);
    return text;
}

}  // namespace varc::includes
