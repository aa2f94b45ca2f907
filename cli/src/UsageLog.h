// SPDX-License-Identifier: Apache-2.0
// The runtime's usage log (docs/USAGE_LOG.md) read back by `--usage-log`: the variants a recorded
// session asked for, planned like ShaderVariantCollection entries.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ProjectInputs.h"
#include "varc/core/Diagnostic.h"
#include "varc/frontend/ShaderLoader.h"
#include "varc/includes/SourceMap.h"

namespace varc::cli {

// One request of a recorded session.
struct UsageEntry {
    std::string shader;  // shader name
    size_t pass = 0;     // index among the shader's passes (LoadedPass::index)
    std::string lightMode;
    std::vector<std::string> keywords;  // as requested
    SourceLocation location;            // its line in the log
};

// Reads a usage log: JSON Lines, first `{"varc_usage_log":1}`, then one
// `{"shader":S,"pass":N,"lightmode":L,"keywords":[...]}` per line. Errors name the line
// (`log:3: error: ...`); nullopt after any.
std::optional<std::vector<UsageEntry>> readUsageLog(const std::string& path,
                                                    includes::SourceMap& sourceMap,
                                                    DiagnosticSink& sink);

// Adds |entries| to |inputs|' demands as collection entries of the pass they name, for the
// shaders of |shaders| with that name; an entry naming a shader or pass not loaded is a warning.
void addUsageDemands(const std::vector<UsageEntry>& entries,
                     const std::vector<frontend::LoadedShader>& shaders, ProjectInputs& inputs,
                     DiagnosticSink& sink);

}  // namespace varc::cli
