// SPDX-License-Identifier: Apache-2.0
// Options -> driver::BuildOptions for `build` and `explain`.
#include "varc/cli/DriverOptions.h"

#include <cstdlib>
#include <filesystem>
#include <string_view>
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

// The optimiser's worker pool: varc itself, re-executed (OptimizerWorker.h). Environment knobs
// (for diagnosis and tests, not everyday options): VARC_OPTIMIZER_WORKERS=0 optimises in this
// process; VARC_WORKER_TIMEOUT=SECONDS bounds one program's optimisation (default 300).
bool gOptimizerWorkersEnabled = false;  // set once by main, before any thread starts

std::shared_ptr<driver::OptimizerPool> optimizerPool() {
    if (!gOptimizerWorkersEnabled) return nullptr;
    const char* workers = std::getenv("VARC_OPTIMIZER_WORKERS");
    if (workers && std::string_view(workers) == "0") return nullptr;
    std::string executable = driver::currentExecutablePath();
    if (executable.empty()) return nullptr;
    int timeoutSeconds = 300;
    if (const char* timeout = std::getenv("VARC_WORKER_TIMEOUT")) {
        int seconds = std::atoi(timeout);
        if (seconds > 0) timeoutSeconds = seconds;
    }
    return std::make_shared<driver::OptimizerPool>(std::move(executable), timeoutSeconds * 1000);
}

}  // namespace

void enableOptimizerWorkers() { gOptimizerWorkersEnabled = true; }

driver::BuildOptions toBuildOptions(const CompileOptions& compile,
                                    const ShaderInputOptions& input) {
    driver::BuildOptions options;
    options.optimization = compile.optimization;
    options.jobs = compile.jobs;
    options.keepGoing = compile.keepGoing;
    options.debugNames = compile.debugNames;
    options.projectKeywords = !compile.noKeywordProjection;
    options.projectReachableCode = !compile.noReachableProjection;
    options.maxVariantsPerPass = compile.maxVariants;
    options.sampleVariantsPerPass = compile.sampleVariants;
    options.shard = compile.shard;
    options.cache = openCacheLevels(compile.cacheLevels);
    options.sourcePaths = sourcePathMap(compile, input);
    options.optimizerPool = optimizerPool();
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
