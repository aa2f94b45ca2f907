// SPDX-License-Identifier: Apache-2.0
// What the commands that read shaders share: the session (files read, diagnostics, the project)
// and loading the inputs, with --project and --strip-rules, into planned shaders.
#pragma once

#include <cstdint>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "ProjectInputs.h"
#include "varc/cli/DiagnosticOutput.h"
#include "varc/cli/Options.h"
#include "varc/cli/RecordingFileSystem.h"
#include "varc/core/Diagnostic.h"
#include "varc/frontend/ShaderLoader.h"
#include "varc/frontend/VariantLimit.h"
#include "varc/includes/FileSystem.h"
#include "varc/includes/SourceMap.h"

namespace varc::cli {

// State shared by the commands: the files read, the diagnostics reported so far and where they
// are written.
struct Session {
    Session(DiagnosticsFormat format, std::ostream& err) : output(format, sourceMap, err) {}

    includes::DiskFileSystem disk;
    RecordingFileSystem fileSystem{disk};  // records what `build --direct` read
    includes::SourceMap sourceMap;
    DiagnosticList diagnostics;
    DiagnosticOutput output;
    size_t printed = 0;                    // diagnostics already written
    std::optional<ProjectInputs> project;  // --project: what the project asked for

    // Writes the diagnostics reported since the last call, as found by |rule|.
    void printNew(DiagnosticRule rule) {
        const std::vector<Diagnostic>& all = diagnostics.diagnostics();
        output.print(
            std::vector<Diagnostic>(all.begin() + static_cast<std::ptrdiff_t>(printed), all.end()),
            rule);
        printed = all.size();
    }
};

// Loads every input shader (with --project, the project's build) and plans its variants (with
// --project or --strip-rules); false when any failed (diagnostics are in |session|). With
// |failedFiles|, a shader file that fails to load is listed there instead of failing the load.
bool loadAll(const ShaderInputOptions& input, Session& session,
             std::vector<frontend::LoadedShader>& shaders,
             uint64_t maxVariants = frontend::kDefaultMaxVariantsPerPass,
             std::vector<std::string>* failedFiles = nullptr);

}  // namespace varc::cli
