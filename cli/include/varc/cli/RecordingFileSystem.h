// SPDX-License-Identifier: Apache-2.0
// RecordingFileSystem: a FileSystem that forwards to another and, when asked to, records every
// question with its answer, for the manifest of `varc build --direct` (BuildManifest.h).
#pragma once

#include <map>
#include <mutex>
#include <utility>
#include <vector>

#include "varc/cli/BuildManifest.h"
#include "varc/includes/FileSystem.h"

namespace varc::cli {

class RecordingFileSystem final : public includes::FileSystem {
public:
    // Forwards to |inner|, which must outlive this; records nothing until startRecording().
    explicit RecordingFileSystem(const includes::FileSystem& inner) : mInner(inner) {}

    std::optional<std::string> read(const std::string& path) const override;
    bool isFile(const std::string& path) const override;
    std::vector<std::string> fileNames(const std::string& dir) const override;

    void startRecording();
    bool recording() const;
    // Each question asked since startRecording(), once, in the order first asked, with the
    // answer it got then. Thread-safe.
    std::vector<FileQuery> queries() const;

private:
    void record(FileQueryKind kind, const std::string& path, std::string answer) const;

    const includes::FileSystem& mInner;
    mutable std::mutex mMutex;
    bool mRecording = false;
    mutable std::map<std::pair<FileQueryKind, std::string>, size_t> mSeen;  // -> mQueries index
    mutable std::vector<FileQuery> mQueries;
};

}  // namespace varc::cli
