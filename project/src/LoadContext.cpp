// SPDX-License-Identifier: Apache-2.0
// File ids, warnings and bounded file reading for one loadProject call.
#include "LoadContext.h"

#include "varc/core/FileRead.h"

namespace varc::project {

namespace {
constexpr size_t kMaxAssetBytes = size_t{64} << 20;
}

LoadContext::LoadContext(Project& project, DiagnosticSink& sink, const LoadOptions& options)
    : mProject(project), mSink(sink), mOptions(options) {}

FileId LoadContext::fileId(const std::filesystem::path& file) {
    auto found = mIds.find(file);
    if (found != mIds.end()) return found->second;
    FileId id = 0;
    if (mOptions.fileIdFor) {
        id = mOptions.fileIdFor(file);
    } else {
        id = static_cast<FileId>(mProject.files.size());
        mProject.files.push_back(file);
    }
    mIds.emplace(file, id);
    return id;
}

void LoadContext::warn(const std::filesystem::path& file, uint32_t line, uint32_t column,
                       std::string message) {
    mSink.warning(SourceLocation{fileId(file), line, line == 0 ? 0 : column}, std::move(message));
}

std::optional<std::string> LoadContext::readText(const std::filesystem::path& file) {
    Result<std::string> text = readFile(file.string(), kMaxAssetBytes);
    if (!text) {
        warn(file, "cannot read: " + text.error().detail);
        return std::nullopt;
    }
    return std::move(*text);
}

}  // namespace varc::project
