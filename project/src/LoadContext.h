// SPDX-License-Identifier: Apache-2.0
// What every reader of one loadProject call shares: the sink, file ids and file reading.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "varc/core/Diagnostic.h"
#include "varc/project/Project.h"

namespace varc::project {

class LoadContext {
public:
    LoadContext(Project& project, DiagnosticSink& sink, const LoadOptions& options);

    const LoadOptions& options() const { return mOptions; }

    // The FileId of |file|: from LoadOptions::fileIdFor, else its index in Project::files.
    FileId fileId(const std::filesystem::path& file);
    // Reports `file:line:col: warning: message`; |line| 0 = the file as a whole.
    void warn(const std::filesystem::path& file, uint32_t line, uint32_t column,
              std::string message);
    void warn(const std::filesystem::path& file, std::string message) {
        warn(file, 0, 0, std::move(message));
    }
    // The contents of |file|, or nullopt after a warning (unreadable, or over 64 MiB: no asset
    // varc reads is that large, and a bound keeps a stray file from exhausting memory).
    std::optional<std::string> readText(const std::filesystem::path& file);

private:
    Project& mProject;
    DiagnosticSink& mSink;
    const LoadOptions& mOptions;
    std::map<std::filesystem::path, FileId> mIds;
};

}  // namespace varc::project
