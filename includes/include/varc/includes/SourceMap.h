// SPDX-License-Identifier: Apache-2.0
// Registry of source files: FileId <-> path and contents, so diagnostics can print paths.
#pragma once

#include <deque>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "varc/core/SourceLocation.h"

namespace varc::includes {

// Every file varc reads gets one FileId. FileIds are dense from 0 and are also the source-string
// numbers written in `#line <line> <fileId>` directives, so glslang's "ERROR: 3:12:" maps back.
// Not thread-safe for writes; register files before fanning out.
class SourceMap {
public:
    // Registers |path| with |contents| and returns its new id. The path is stored normalised
    // (normalizePath), so "a/./b.h" and "a/b.h" are one file; registering a path again returns
    // the existing id and keeps the first contents.
    FileId addFile(const std::string& path, std::string contents);
    // The id of |path| (normalised first), or nullopt when it was never registered.
    std::optional<FileId> find(const std::string& path) const;

    // The normalised path and the contents of |id|; |id| must have been returned by addFile.
    const std::string& path(FileId id) const;
    const std::string& contents(FileId id) const;
    size_t size() const { return mFiles.size(); }

    // Text of 1-based |line| in |id| without its newline, or "" when out of range.
    std::string lineText(FileId id, uint32_t line) const;
    // "path:line:col", "path:line" when the column is 0, "<unknown>" for kNoFile.
    std::string format(SourceLocation location) const;

private:
    struct File {
        std::string path;
        std::string contents;
        std::vector<size_t> lineStarts;  // offset of each line's first character
    };
    std::deque<File> mFiles;  // deque: references stay valid as files are added
    std::unordered_map<std::string, FileId> mByPath;
};

}  // namespace varc::includes
