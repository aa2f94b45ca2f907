// SPDX-License-Identifier: Apache-2.0
// RecordingFileSystem: forwards file-system questions and records them with their answers.
#include "varc/cli/RecordingFileSystem.h"

namespace varc::cli {

std::optional<std::string> RecordingFileSystem::read(const std::string& path) const {
    std::optional<std::string> bytes = mInner.read(path);
    if (recording()) record(FileQueryKind::Read, path, bytes ? contentDigest(*bytes) : "-");
    return bytes;
}

bool RecordingFileSystem::isFile(const std::string& path) const {
    bool file = mInner.isFile(path);
    record(FileQueryKind::IsFile, path, file ? "1" : "0");
    return file;
}

std::vector<std::string> RecordingFileSystem::fileNames(const std::string& dir) const {
    std::vector<std::string> names = mInner.fileNames(dir);
    if (!recording()) return names;
    std::string joined;
    for (const std::string& name : names) joined += name + '\n';
    record(FileQueryKind::List, dir, contentDigest(joined));
    return names;
}

void RecordingFileSystem::startRecording() {
    std::lock_guard<std::mutex> lock(mMutex);
    mRecording = true;
}

bool RecordingFileSystem::recording() const {
    std::lock_guard<std::mutex> lock(mMutex);
    return mRecording;
}

std::vector<FileQuery> RecordingFileSystem::queries() const {
    std::lock_guard<std::mutex> lock(mMutex);
    return mQueries;
}

void RecordingFileSystem::record(FileQueryKind kind, const std::string& path,
                                 std::string answer) const {
    std::lock_guard<std::mutex> lock(mMutex);
    if (!mRecording) return;
    // The first answer is what the build used; a later, different one (the file changed while
    // the build ran) makes the record inconsistent, so it is kept too and can never all hold.
    auto [it, inserted] = mSeen.emplace(std::make_pair(kind, path), mQueries.size());
    if (inserted || mQueries[it->second].answer != answer) {
        mQueries.push_back({kind, path, std::move(answer)});
    }
}

}  // namespace varc::cli
