// SPDX-License-Identifier: Apache-2.0
// The parsed `varc` command line: one typed options struct per subcommand, decoded and checked
// when parsed, so a command never sees a value it has to reject.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "varc/cache/CacheSpec.h"
#include "varc/driver/ShardPlan.h"
#include "varc/driver/SpirvOptimizer.h"
#include "varc/frontend/VariantLimit.h"
#include "varc/variants/LightKeywords.h"
#include "varc/variants/VariantSelector.h"

namespace varc::cli {

// How diagnostics are written to standard error (`--diagnostics-format`): clang style (the
// default, for people), one JSON document, GitHub Actions workflow commands, or SARIF 2.1.0.
enum class DiagnosticsFormat { Clang, Json, Github, Sarif };

// A growth allowance for `varc check --max-growth`: N variants, or N percent of the lock.
struct GrowthLimit {
    double amount = 0;
    bool percent = false;
    friend bool operator==(const GrowthLimit&, const GrowthLimit&) = default;
};

// The defaults the help text quotes, each written once.
inline constexpr int kDefaultCompressionLevel = 19;  // build --compression-level (zstd, 1..22)
inline constexpr int kMinCompressionLevel = 1;
inline constexpr int kMaxCompressionLevel = 22;
inline constexpr unsigned kAllCores = 0;  // -j: hardware concurrency
inline constexpr const char* kDefaultScenesDir = "tests/scenes/forward";  // validate --scenes
inline constexpr const char* kDefaultValidateOut = "validate-out";        // validate --out

// What every command that reads shaders takes: the PATH arguments and where includes are found.
struct ShaderInputOptions {
    std::vector<std::string> inputs;       // files, or directories searched for *.shader
    std::vector<std::string> includeDirs;  // -I
    std::string projectRoot;               // --project-root ("" = found from each shader)
    // --builtin-include-dir, else $VARC_BUILTIN_INCLUDE_DIR, else the installed or source default.
    std::string builtinIncludeDir;
    // --project: a Unity project whose materials, variant collections and Graphics Settings
    // choose the variants (docs/PROJECTS.md); "" = every declared variant of the PATHs.
    std::string projectDir;
    std::vector<std::string> projectShaders;     // --project-shaders: the shaders' own folders
    std::vector<std::string> builtinShaderDirs;  // --builtin-shaders: Unity's built-in shaders
    std::string stripRulesPath;          // --strip-rules: the user's strip rules ("" = none)
    std::vector<std::string> usageLogs;  // --usage-log: sessions the runtime recorded
    DiagnosticsFormat diagnosticsFormat = DiagnosticsFormat::Clang;  // --diagnostics-format
};

// The flags `build` and `explain` hand to the driver (toBuildOptions); explain has flags only for
// jobs and maxVariants, and the others keep these defaults, which are the driver's.
struct CompileOptions {
    unsigned jobs = kAllCores;                                    // -j N
    uint64_t maxVariants = frontend::kDefaultMaxVariantsPerPass;  // --max-variants N per pass
    uint64_t sampleVariants = 0;  // --sample-variants N per pass (0: every variant)
    driver::OptimizationLevel optimization = driver::OptimizationLevel::Performance;  // -O0|-O|-Os
    bool keepGoing = false;   // --keep-going
    bool debugNames = false;  // -g, --debug-names
    // --no-keyword-projection: preprocess once per variant's observed defines, as before the
    // keyword projection (BuildOptions::projectKeywords); same pack, for measuring and checking.
    bool noKeywordProjection = false;
    // --no-reachable-projection: count lookups in unreachable code too
    // (BuildOptions::projectReachableCode); same pack, for measuring and checking.
    bool noReachableProjection = false;
    driver::ShardSpec shard;  // --shard K/N (1/1: all)
    // The program cache's levels in order: --cache-dir DIR (or $VARC_CACHE_DIR) as a folder
    // level, then each --cache URL (or $VARC_CACHE's).
    std::vector<cache::CacheSpec> cacheLevels;
    std::vector<std::string> filePrefixMaps;  // --file-prefix-map OLD=NEW, each checked
};

// `varc variants [--json] [--list] [--max-variants N] PATH...`
struct VariantsOptions {
    ShaderInputOptions input;
    bool json = false;
    bool list = false;  // --list: every variant in enumeration order
    uint64_t maxVariants = frontend::kDefaultMaxVariantsPerPass;  // checked with --list only
};

// `varc lock -o FILE PATH...`
struct LockOptions {
    ShaderInputOptions input;
    std::string lockPath;
    uint64_t maxVariants = frontend::kDefaultMaxVariantsPerPass;
};

// `varc check --lock FILE [--max-growth N|N% | --budget N] PATH...`
struct CheckOptions {
    ShaderInputOptions input;
    std::string lockPath;
    std::optional<GrowthLimit> maxGrowth;
    std::optional<uint64_t> budget;
};

// `varc build -o PACK [...] PATH...`
struct BuildCommandOptions {
    ShaderInputOptions input;
    CompileOptions compile;
    std::string outputPath;   // -o
    std::string depfilePath;  // --depfile ("" = none)
    bool json = false;
    int compressionLevel = kDefaultCompressionLevel;
    // --direct: with a cache, reuse an earlier build's pack when no file it read has changed.
    bool direct = false;
    // --skip-failing-shaders: as a Unity player build does, a shader that fails to load, compile
    // or assemble is reported and left out of the pack instead of failing the build.
    bool skipFailingShaders = false;
};

// `varc merge -o PACK PART...`
struct MergeOptions {
    std::vector<std::string> parts;
    std::string outputPath;
};

// `varc info [--json] PACK`
struct InfoOptions {
    std::string packPath;
    bool json = false;
};

// `varc extract PACK -o DIR`
struct ExtractOptions {
    std::string packPath;
    std::string outputDir;
};

// `varc lookup PACK --shader NAME --pass N|LIGHTMODE (--keywords "A B" | --light TYPE ...)`
struct LookupOptions {
    std::string packPath;
    std::string shader;
    std::string pass;
    std::vector<std::string>
        keywords;  // --keywords, split at spaces (with --light: the material's)
    std::optional<variants::LightDescription> light;  // --light with --cookie, --shadows, ...
    variants::SelectionPolicy policy = variants::SelectionPolicy::Closest;
    bool json = false;
};

// `varc explain --shader NAME --pass N|LIGHTMODE [--variant "A B"] [--diff "A B" "C D"] PATH...`
struct ExplainOptions {
    ShaderInputOptions input;
    CompileOptions compile;  // -j and --max-variants; the rest as the driver's defaults
    std::string shader;
    std::string pass;
    std::optional<std::string> variant;  // --variant's keywords as written ("" = none)
    std::optional<std::pair<std::string, std::string>> diff;  // --diff "A B" "C D" as written
    bool json = false;
};

// What render and validate open: the packs and the --pipeline-cache file ("" = none).
struct RenderSessionOptions {
    std::vector<std::string> packPaths;
    std::string pipelineCachePath;
};

// `varc render PACK... --scene S.json -o OUT.png [--reference R.png] [--diff D.png]
// [--variant-policy closest|strict] [--usage-log FILE]`
struct RenderOptions {
    RenderSessionOptions session;
    std::string scenePath;
    std::string outputPath;
    std::string referencePath;  // "" = none
    std::string diffPath;       // "" = none
    // What a draw whose material and lights ask for a variant the pack lacks gets: Closest
    // (Unity's default; a warning once per request) or Strict (an error, exit 1).
    variants::SelectionPolicy variantPolicy = variants::SelectionPolicy::Closest;
    std::string usageLogPath;  // "" = none; docs/USAGE_LOG.md
};

// `varc validate --pack PACK... [--scenes DIR | --properties] [--out DIR] [--report PAGE]`
struct ValidateOptions {
    RenderSessionOptions session;
    std::string scenesDir = kDefaultScenesDir;
    std::string outputDir = kDefaultValidateOut;
    std::string reportPath;  // "" = none
    bool properties = false;
    bool listUncovered = false;
};

// `varc cache stats [--json]` and `varc cache clear`, over the --cache levels (or $VARC_CACHE's).
struct CacheOptions {
    enum class Action { Stats, Clear };
    Action action = Action::Stats;
    std::vector<cache::CacheSpec> levels;
    bool json = false;
};

// The one command a command line runs, with its options.
using CommandOptions = std::variant<VariantsOptions, LockOptions, CheckOptions, BuildCommandOptions,
                                    MergeOptions, InfoOptions, ExtractOptions, LookupOptions,
                                    ExplainOptions, RenderOptions, ValidateOptions, CacheOptions>;

// Exit codes shared by every subcommand.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;  // input errors; for `check`, a mismatch
inline constexpr int kExitUsage = 2;    // bad command line; for `check`, also input errors

// What parsing a command line ended with: the command to run, or an exit code when parsing ended
// the run (help or --version printed to |out|, a usage error printed to |err|, or the hidden
// `_generate` command wrote the man page or bash completion from this definition).
struct ParsedCommandLine {
    std::optional<CommandOptions> command;
    int exitCode = kExitOk;  // meaningful without a command
};

// Parses |argv| (argv[0] is the program). Every value is decoded and checked here: a bad -O,
// --shard, --policy, --light, --shadows, --max-growth, --compression-level, cache URL or
// conflicting flags are a usage error (kExitUsage) printed to |err|. Reads VARC_CACHE,
// VARC_CACHE_DIR and VARC_BUILTIN_INCLUDE_DIR when their flags are absent.
ParsedCommandLine parseCommandLine(int argc, const char* const* argv, std::ostream& out,
                                   std::ostream& err);

}  // namespace varc::cli
