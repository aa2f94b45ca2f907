// SPDX-License-Identifier: Apache-2.0
// The CLI11 definition of the commands that read shaders: variants, lock, check, build, explain.
#include <cstdlib>
#include <memory>
#include <utility>

#include "OptionDefinitions.h"
#include "varc/includes/SourcePathMap.h"

namespace varc::cli {

namespace {

// "12" -> 12 variants; "10%" -> 10 percent; nullopt for anything else.
std::optional<GrowthLimit> parseGrowth(const std::string& text) {
    GrowthLimit limit;
    std::string number = text;
    if (!number.empty() && number.back() == '%') {
        limit.percent = true;
        number.pop_back();
    }
    char* end = nullptr;
    limit.amount = std::strtod(number.c_str(), &end);
    if (number.empty() || end != number.c_str() + number.size() || limit.amount < 0) {
        return std::nullopt;
    }
    return limit;
}

// Sets state.finish, when |command| runs, to return |options| with its shader inputs finished.
template <typename T>
void finishWithInput(CLI::App& command, ParseState& state, std::shared_ptr<T> options) {
    command.callback([&state, options] {
        state.finish = [options]() -> Result<CommandOptions> {
            if (Status input = finishInput(options->input); !input) return input.error();
            return CommandOptions(*options);
        };
    });
}

// --optimization LEVEL (what -O0, -O and -Os become), decoded into |level|.
void addOptimization(CLI::App& command, driver::OptimizationLevel& level) {
    command
        .add_option_function<std::string>(
            "--optimization",
            [&level](const std::string& text) { level = *driver::parseOptimizationLevel(text); },
            "Optimisation level; also written -O0, -O (default), -Os")
        ->type_name("LEVEL")
        ->check(CLI::IsMember({"-O0", "-O", "-Os"}));
}

// --shard K/N, decoded into |shard|.
void addShard(CLI::App& command, driver::ShardSpec& shard) {
    command
        .add_option_function<std::string>(
            "--shard", [&shard](const std::string& text) { shard = *driver::parseShardSpec(text); },
            "Compile only shard K of N of the distinct programs into a partial pack "
            "(join the N parts with `varc merge`)")
        ->type_name("K/N")
        ->check([](const std::string& text) {
            return driver::parseShardSpec(text)
                       ? std::string()
                       : "expected K/N with 1 <= K <= N <= " + std::to_string(driver::kMaxShards) +
                             ", got '" + text + "'";
        });
}

void addFilePrefixMaps(CLI::App& command, std::vector<std::string>& rules) {
    command
        .add_option("--file-prefix-map", rules,
                    "Record source paths starting with OLD as starting with NEW (as GCC's "
                    "-ffile-prefix-map; other paths inside the project root are recorded "
                    "relative to it)")
        ->allow_extra_args(false)
        ->type_name("OLD=NEW")
        ->check([](const std::string& rule) {
            return includes::SourcePathMap().addRule(rule) ? std::string()
                                                           : "expected OLD=NEW, got '" + rule + "'";
        });
}

// What `build` parses besides its options: the cache flags, decoded when the parse ends.
struct BuildFlags {
    BuildCommandOptions options;
    std::string cacheDirectory;
    std::vector<std::string> cacheUrls;
};

void addBuildOutputs(CLI::App& cmd, BuildCommandOptions& options) {
    cmd.add_option("-o,--output", options.outputPath, "Pack file to write")
        ->required()
        ->type_name("FILE");
    addJobs(cmd, options.compile.jobs);
    addOptimization(cmd, options.compile.optimization);
    cmd.add_option("--depfile", options.depfilePath, "Write a Make-style dependency file")
        ->type_name("FILE");
    cmd.add_flag("--json", options.json, "Print the build summary as JSON");
    cmd.add_flag("--keep-going", options.compile.keepGoing,
                 "Compile everything to report all errors");
    cmd.add_option("--compression-level", options.compressionLevel,
                   "zstd level of the pack's blobs, " + std::to_string(kMinCompressionLevel) + "-" +
                       std::to_string(kMaxCompressionLevel) + " (default " +
                       std::to_string(kDefaultCompressionLevel) + "; 3 writes faster, ~20% bigger)")
        ->check(CLI::Range(kMinCompressionLevel, kMaxCompressionLevel));
    cmd.add_flag("--direct", options.direct,
                 "With a cache: reuse the pack of an earlier build whose files are unchanged");
    cmd.add_flag("--skip-failing-shaders", options.skipFailingShaders,
                 "Leave a shader that fails out of the pack (its errors reported), as Unity's "
                 "player build does, instead of failing the build");
    cmd.add_flag("-g,--debug-names", options.compile.debugNames,
                 "Keep OpName/OpMemberName in the SPIR-V (bigger packs; for GPU debuggers)");
    addMaxVariants(cmd, options.compile.maxVariants);
    cmd.add_option("--sample-variants", options.compile.sampleVariants,
                   "Build at most N variants per pass, spread evenly over its variants (first and "
                   "last included): a quick check that every pass compiles, not a pack to ship")
        ->type_name("N")
        ->check(CLI::PositiveNumber);
    cmd.add_flag("--no-keyword-projection", options.compile.noKeywordProjection,
                 "Preprocess each variant's keywords, not only those its branches look up "
                 "(same pack; for measuring and checking)");
    cmd.add_flag("--no-reachable-projection", options.compile.noReachableProjection,
                 "Count the keyword lookups made in code a stage's entry point cannot reach too "
                 "(same pack; for measuring and checking)");
}

}  // namespace

void addVariants(CLI::App& app, ParseState& state) {
    auto options = std::make_shared<VariantsOptions>();
    CLI::App* cmd = app.add_subcommand("variants", "List passes, keyword sets and variant counts");
    cmd->add_flag("--json", options->json, "Print JSON");
    cmd->add_flag("--list", options->list, "List every variant in enumeration order");
    addMaxVariants(*cmd, options->maxVariants);
    addDiagnosticsFormat(*cmd, options->input);
    addInputOptions(*cmd, options->input);
    finishWithInput(*cmd, state, options);
}

void addLock(CLI::App& app, ParseState& state) {
    auto options = std::make_shared<LockOptions>();
    CLI::App* cmd = app.add_subcommand("lock", "Write variant counts to a lock file");
    cmd->add_option("-o,--output", options->lockPath, "Lock file to write")
        ->required()
        ->type_name("FILE");
    addMaxVariants(*cmd, options->maxVariants);
    addDiagnosticsFormat(*cmd, options->input);
    addInputOptions(*cmd, options->input);
    finishWithInput(*cmd, state, options);
}

void addCheck(CLI::App& app, ParseState& state) {
    auto options = std::make_shared<CheckOptions>();
    auto growthText = std::make_shared<std::string>();
    CLI::App* cmd = app.add_subcommand("check", "Compare variant counts with a lock file");
    cmd->add_option("--lock", options->lockPath, "Lock file to compare with")
        ->required()
        ->type_name("FILE");
    auto* growth = cmd->add_option("--max-growth", *growthText,
                                   "Allow each shader to grow by N variants (or N%)")
                       ->type_name("N|N%");
    cmd->add_option("--budget", options->budget, "Fail when a shader has more than N variants")
        ->excludes(growth);
    addDiagnosticsFormat(*cmd, options->input);
    addInputOptions(*cmd, options->input);
    cmd->callback([&state, options, growthText] {
        state.finish = [options, growthText]() -> Result<CommandOptions> {
            if (!growthText->empty()) {
                options->maxGrowth = parseGrowth(*growthText);
                if (!options->maxGrowth) {
                    return usageError("--max-growth expects N or N%, got '" + *growthText + "'");
                }
            }
            if (Status input = finishInput(options->input); !input) return input.error();
            return CommandOptions(*options);
        };
    });
}

void addBuild(CLI::App& app, ParseState& state) {
    auto flags = std::make_shared<BuildFlags>();
    BuildCommandOptions& options = flags->options;
    CLI::App* cmd = app.add_subcommand("build", "Compile every variant into a SPIR-V pack");
    addBuildOutputs(*cmd, options);
    cmd->add_option("--cache-dir", flags->cacheDirectory,
                    "Reuse and store compiled programs in this folder (ccache-like)")
        ->envname("VARC_CACHE_DIR")
        ->type_name("DIR");
    addShard(*cmd, options.compile.shard);
    addFilePrefixMaps(*cmd, options.compile.filePrefixMaps);
    addCacheUrls(*cmd, flags->cacheUrls);
    addDiagnosticsFormat(*cmd, options.input);
    addInputOptions(*cmd, options.input);
    cmd->callback([&state, flags] {
        state.finish = [flags]() -> Result<CommandOptions> {
            auto levels = cacheLevelsOf(flags->cacheDirectory, flags->cacheUrls);
            if (!levels) return levels.error();
            flags->options.compile.cacheLevels = std::move(*levels);
            // Which shaders fail is decided per whole shader: a shard sees only some variants,
            // and a direct hit would not report the errors again.
            if (flags->options.skipFailingShaders && !flags->options.compile.shard.whole())
                return usageError("--skip-failing-shaders cannot be combined with --shard");
            if (flags->options.skipFailingShaders && flags->options.direct)
                return usageError("--skip-failing-shaders cannot be combined with --direct");
            if (Status input = finishInput(flags->options.input); !input) return input.error();
            return CommandOptions(flags->options);
        };
    });
}

void addExplain(CLI::App& app, ParseState& state) {
    auto options = std::make_shared<ExplainOptions>();
    auto diff = std::make_shared<std::vector<std::string>>();
    CLI::App* cmd =
        app.add_subcommand("explain",
                           "Show which keywords change which stage's program in a pass, and why a "
                           "variant exists");
    cmd->add_option("--shader", options->shader, "Shader name")->required()->type_name("NAME");
    cmd->add_option("--pass", options->pass, "Pass index or LightMode")
        ->required()
        ->type_name("N|LIGHTMODE");
    cmd->add_option("--variant", options->variant,
                    "Explain this variant: its keywords, space-separated (\"\" = none)")
        ->type_name("\"A B\"");
    cmd->add_option("--diff", *diff, "Compare the pruned sources of two variants, stage by stage")
        ->expected(2)
        ->type_name("\"A B\" \"C D\"");
    addJobs(*cmd, options->compile.jobs);
    cmd->add_flag("--json", options->json, "Print JSON");
    addMaxVariants(*cmd, options->compile.maxVariants);
    addDiagnosticsFormat(*cmd, options->input);
    addInputOptions(*cmd, options->input);
    cmd->callback([&state, options, diff] {
        state.finish = [options, diff]() -> Result<CommandOptions> {
            if (diff->size() == 2) options->diff = std::make_pair((*diff)[0], (*diff)[1]);
            if (Status input = finishInput(options->input); !input) return input.error();
            return CommandOptions(*options);
        };
    });
}

}  // namespace varc::cli
