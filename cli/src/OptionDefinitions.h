// SPDX-License-Identifier: Apache-2.0
// The CLI11 definition of each subcommand family, shared by the parser and the generated docs.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "varc/cli/Options.h"
#include "varc/core/Result.h"

namespace varc::cli {

// What the parse leaves behind: the chosen subcommand's last step, which decodes what CLI11 kept
// as text and returns its options, or the usage error ("--policy expects ..., got 'x'").
struct ParseState {
    std::function<Result<CommandOptions>()> finish;
    // `_generate WHAT -o FILE` (hidden): written by the parser itself.
    std::optional<std::string> generateWhat;
    std::string generateOutput;
};

// The usage error |detail| as finish() returns it.
Error usageError(std::string detail);

// Shared flags. -I, --project-root, --builtin-include-dir and the PATH arguments:
void addInputOptions(CLI::App& command, ShaderInputOptions& input);
// --diagnostics-format FORMAT, decoded as given:
void addDiagnosticsFormat(CLI::App& command, ShaderInputOptions& input);
// --max-variants N (default frontend::kDefaultMaxVariantsPerPass):
void addMaxVariants(CLI::App& command, uint64_t& maxVariants);
// -j, --jobs N (default: all cores):
void addJobs(CLI::App& command, unsigned& jobs);
// --cache URL, repeatable, kept as written in |urls| for cacheLevelsOf:
void addCacheUrls(CLI::App& command, std::vector<std::string>& urls);

// Completes |input| after the parse: the built-in include folder when none was given. An error
// when there is nothing to read (no PATH and no --project).
Status finishInput(ShaderInputOptions& input);

// The cache levels in order: |directory| (--cache-dir or $VARC_CACHE_DIR) as one folder level
// unless empty, then |urls| (or, when there are none, $VARC_CACHE's), each parsed; an error
// quotes the malformed URL.
Result<std::vector<cache::CacheSpec>> cacheLevelsOf(const std::string& directory,
                                                    const std::vector<std::string>& urls);

// One function per subcommand, in the order --help lists them; each sets state.finish when its
// subcommand runs. ShaderCommandOptions.cpp:
void addVariants(CLI::App& app, ParseState& state);
void addLock(CLI::App& app, ParseState& state);
void addCheck(CLI::App& app, ParseState& state);
void addBuild(CLI::App& app, ParseState& state);
void addExplain(CLI::App& app, ParseState& state);
// PackCommandOptions.cpp:
void addMerge(CLI::App& app, ParseState& state);
void addInfo(CLI::App& app, ParseState& state);
void addExtract(CLI::App& app, ParseState& state);
void addLookup(CLI::App& app, ParseState& state);
// RenderCommandOptions.cpp:
void addRender(CLI::App& app, ParseState& state);
void addValidate(CLI::App& app, ParseState& state);
void addCache(CLI::App& app, ParseState& state);

}  // namespace varc::cli
