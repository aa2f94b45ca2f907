// SPDX-License-Identifier: Apache-2.0
// Options -> driver::BuildOptions for `build` and `explain`.
#include "varc/cli/DriverOptions.h"

#include <filesystem>
#include <system_error>

#include "varc/cli/CacheCommands.h"

namespace varc::cli {

namespace {

// How the pack records source paths: relative to --project-root (default: the current folder),
// with the --file-prefix-map rules (checked when parsed).
includes::SourcePathMap sourcePathMap(const CompileOptions& compile,
                                      const ShaderInputOptions& input) {
    std::error_code error;
    std::filesystem::path root = input.projectRoot.empty()
                                     ? std::filesystem::current_path(error)
                                     : std::filesystem::absolute(input.projectRoot, error);
    includes::SourcePathMap map(error ? std::string() : root.lexically_normal().string());
    for (const std::string& rule : compile.filePrefixMaps) map.addRule(rule);
    return map;
}

}  // namespace

driver::BuildOptions toBuildOptions(const CompileOptions& compile,
                                    const ShaderInputOptions& input) {
    driver::BuildOptions options;
    options.optimization = compile.optimization;
    options.jobs = compile.jobs;
    options.keepGoing = compile.keepGoing;
    options.debugNames = compile.debugNames;
    options.projectKeywords = !compile.noKeywordProjection;
    options.maxVariantsPerPass = compile.maxVariants;
    options.shard = compile.shard;
    options.cache = openCacheLevels(compile.cacheLevels);
    options.sourcePaths = sourcePathMap(compile, input);
    return options;
}

std::string optimizationFlag(driver::OptimizationLevel level) {
    switch (level) {
        case driver::OptimizationLevel::None:
            return "-O0";
        case driver::OptimizationLevel::Size:
            return "-Os";
        case driver::OptimizationLevel::Performance:
            break;
    }
    return "-O";
}

}  // namespace varc::cli
