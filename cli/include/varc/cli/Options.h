// SPDX-License-Identifier: Apache-2.0
// The parsed `varc` command line, one struct for every subcommand.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace varc::cli {

enum class Command {
    None,
    Variants,
    Lock,
    Check,
    Build,
    Merge,
    Info,
    Extract,
    Lookup,
    Render,
    Validate,
    Explain,
    Generate,
    CacheStats,
    CacheClear
};

// How diagnostics are written to standard error (`--diagnostics-format`): clang style (the
// default, for people), one JSON document, GitHub Actions workflow commands, or SARIF 2.1.0.
enum class DiagnosticsFormat { Clang, Json, Github, Sarif };

// A growth allowance for `varc check --max-growth`: N variants, or N percent of the lock.
struct GrowthLimit {
    double amount = 0;
    bool percent = false;
};

struct Options {
    Command command = Command::None;
    std::vector<std::string> inputs;       // files, or directories searched for *.shader
    std::vector<std::string> includeDirs;  // -I
    std::string projectRoot;               // --project-root ("" = found from each shader)
    std::string builtinIncludeDir;         // --builtin-include-dir or VARC_BUILTIN_INCLUDE_DIR
    bool json = false;                     // --json
    DiagnosticsFormat diagnosticsFormat = DiagnosticsFormat::Clang;  // --diagnostics-format
    bool list = false;                     // --list (variants), --list-uncovered (validate)
    std::string lockPath;                  // lock: -o; check: --lock
    std::optional<GrowthLimit> maxGrowth;  // check --max-growth N|N%
    std::optional<uint64_t> budget;        // check --budget N
    // build
    std::string outputPath;                   // -o OUT.svpack
    std::string depfilePath;                  // --depfile F
    unsigned jobs = 0;                        // -j N; 0 = hardware concurrency
    std::string optimization = "-O";          // -O0 | -O | -Os
    bool keepGoing = false;                   // --keep-going
    std::string cacheDirectory;               // --cache-dir DIR or VARC_CACHE_DIR (= file:DIR)
    std::vector<std::string> cacheUrls;       // --cache URL (repeat; build, cache) or VARC_CACHE
    uint64_t maxVariants = 10'000'000;        // --max-variants N: per pass, for build and --list
    bool debugNames = false;                  // -g, --debug-names
    int compressionLevel = 19;                // --compression-level N (zstd, 1..22)
    std::string shard;                        // --shard K/N ("" = the whole build)
    std::vector<std::string> filePrefixMaps;  // --file-prefix-map OLD=NEW
    // merge: the parts are |inputs|, the pack |outputPath|
    // info / extract / lookup
    std::string packPath;                  // the PACK argument
    std::string lookupShader;              // --shader NAME
    std::string lookupPass;                // --pass N|LIGHTMODE
    std::string lookupKeywords;            // --keywords "A B" (with --light: the material's)
    std::string lookupLight;               // --light directional|point|spot
    bool lookupCookie = false;             // --cookie
    std::string lookupShadows = "none";    // --shadows none|hard|soft
    int lookupVertexLights = 0;            // --vertex-lights N
    bool lookupHdr = false;                // --hdr
    std::string lookupPolicy = "closest";  // --policy exact|closest|first|strict
    // explain: inputs, --shader and --pass as for lookup
    std::optional<std::string> explainVariant;  // --variant "A B"
    std::vector<std::string> explainDiff;       // --diff "A B" "C D"
    // render / validate
    std::vector<std::string> packPaths;  // render: PACK...; validate: --pack P...
    std::string scenePath;               // render --scene S.json
    std::string referencePath;           // render --reference ref.png
    std::string diffPath;                // render --diff d.png
    std::string scenesDir;               // validate --scenes DIR
    std::string reportPath;              // validate --report report.html
    bool properties = false;             // validate --properties
    std::string pipelineCachePath;       // render/validate --pipeline-cache FILE
    // _generate (hidden; the build runs it): "man" or "bash-completion", written to outputPath
    std::string generateWhat;
};

// Exit codes shared by every subcommand.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;  // input errors; for `check`, a mismatch
inline constexpr int kExitUsage = 2;    // bad command line; for `check`, also input errors

// Parses |argv| into |options|. Returns nullopt to continue, or an exit code when parsing
// ended the run (help or --version printed to |out|, usage error printed to |err|, or the
// hidden `_generate` command wrote the man page or bash completion from this definition).
std::optional<int> parseOptions(int argc, const char* const* argv, Options& options,
                                std::ostream& out, std::ostream& err);

}  // namespace varc::cli
