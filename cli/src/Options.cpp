// SPDX-License-Identifier: Apache-2.0
// Command-line parsing for `varc`, through CLI11, into an Options struct.
#include "varc/cli/Options.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdlib>
#include <map>
#include <ostream>

#include "BashCompletion.h"
#include "BuiltinIncludeDir.h"
#include "ManPage.h"
#include "varc/cache/CacheSpec.h"
#include "varc/core/AtomicFile.h"
#include "varc/driver/PackAssembler.h"
#include "varc/driver/ShardPlan.h"
#include "varc/includes/SourcePathMap.h"

namespace varc::cli {

namespace {

// "12" -> 12 variants; "10%" -> 10 percent.
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

void addInputOptions(CLI::App& command, Options& options) {
    command.add_option("-I,--include-dir", options.includeDirs, "Add an include directory")
        ->type_name("DIR");
    command
        .add_option("--project-root", options.projectRoot,
                    "Folder that #include \"Assets/...\" paths start from (default: the nearest "
                    "folder above the shader that has them)")
        ->type_name("DIR");
    command
        .add_option("--builtin-include-dir", options.builtinIncludeDir,
                    "Override the built-in include directory")
        ->type_name("DIR");
    command.add_option("paths", options.inputs, "Shader files, or directories to search")
        ->required()
        ->type_name("PATH");
}

void addMaxVariants(CLI::App& command, Options& options) {
    command
        .add_option("--max-variants", options.maxVariants,
                    "Refuse a pass with more variants than N before enumerating them "
                    "(default 10000000)")
        ->type_name("N")
        ->check(CLI::PositiveNumber);
}

void addDiagnosticsFormat(CLI::App& command, Options& options) {
    static const std::map<std::string, DiagnosticsFormat> kFormats = {
        {"clang", DiagnosticsFormat::Clang},
        {"json", DiagnosticsFormat::Json},
        {"github", DiagnosticsFormat::Github},
        {"sarif", DiagnosticsFormat::Sarif}};
    command
        .add_option_function<std::string>(
            "--diagnostics-format",
            [&options](const std::string& name) { options.diagnosticsFormat = kFormats.at(name); },
            "How errors and warnings are written to standard error: clang (default), json, "
            "github (Actions annotations) or sarif (SARIF 2.1.0)")
        ->type_name("FORMAT")
        ->check(CLI::IsMember({"clang", "json", "github", "sarif"}));
}

void addVariants(CLI::App& app, Options& options) {
    CLI::App* cmd = app.add_subcommand("variants", "List passes, keyword sets and variant counts");
    cmd->add_flag("--json", options.json, "Print JSON");
    cmd->add_flag("--list", options.list, "List every variant in enumeration order");
    addMaxVariants(*cmd, options);
    addDiagnosticsFormat(*cmd, options);
    addInputOptions(*cmd, options);
    cmd->callback([&options] { options.command = Command::Variants; });
}

void addLock(CLI::App& app, Options& options) {
    CLI::App* cmd = app.add_subcommand("lock", "Write variant counts to a lock file");
    cmd->add_option("-o,--output", options.lockPath, "Lock file to write")
        ->required()
        ->type_name("FILE");
    addMaxVariants(*cmd, options);
    addDiagnosticsFormat(*cmd, options);
    addInputOptions(*cmd, options);
    cmd->callback([&options] { options.command = Command::Lock; });
}

void addCheck(CLI::App& app, Options& options, std::string& growthText) {
    CLI::App* cmd = app.add_subcommand("check", "Compare variant counts with a lock file");
    cmd->add_option("--lock", options.lockPath, "Lock file to compare with")
        ->required()
        ->type_name("FILE");
    auto* growth = cmd->add_option("--max-growth", growthText,
                                   "Allow each shader to grow by N variants (or N%)")
                       ->type_name("N|N%");
    cmd->add_option("--budget", options.budget, "Fail when a shader has more than N variants")
        ->excludes(growth);
    addDiagnosticsFormat(*cmd, options);
    addInputOptions(*cmd, options);
    cmd->callback([&options] { options.command = Command::Check; });
}

// --cache URL, repeatable, levels in order (VARC_CACHE when absent, read in parseOptions).
void addCacheUrls(CLI::App& command, Options& options) {
    command
        .add_option("--cache", options.cacheUrls,
                    "Program cache level, in order (repeat): file:DIR or "
                    "redis://HOST[:PORT][/DB], each with |read-only, |prefix=, |ttl=, "
                    "|connect-timeout=MS, |operation-timeout=MS (default: $VARC_CACHE)")
        ->type_name("URL")
        ->allow_extra_args(false);
}

void addCache(CLI::App& app, Options& options) {
    CLI::App* cmd = app.add_subcommand("cache", "Inspect or empty program cache levels");
    cmd->require_subcommand(1);
    CLI::App* stats = cmd->add_subcommand("stats", "Entries and bytes in each cache level");
    addCacheUrls(*stats, options);
    stats->add_flag("--json", options.json, "Print JSON");
    stats->callback([&options] { options.command = Command::CacheStats; });
    CLI::App* clear = cmd->add_subcommand("clear", "Remove every entry varc stored in each level");
    addCacheUrls(*clear, options);
    clear->callback([&options] { options.command = Command::CacheClear; });
}

void addBuild(CLI::App& app, Options& options) {
    CLI::App* cmd = app.add_subcommand("build", "Compile every variant into a SPIR-V pack");
    cmd->add_option("-o,--output", options.outputPath, "Pack file to write")
        ->required()
        ->type_name("FILE");
    cmd->add_option("-j,--jobs", options.jobs, "Worker threads (default: all cores)");
    cmd->add_option("--optimization", options.optimization,
                    "Optimisation level; also written -O0, -O (default), -Os")
        ->type_name("LEVEL")
        ->check(CLI::IsMember({"-O0", "-O", "-Os"}));
    cmd->add_option("--depfile", options.depfilePath, "Write a Make-style dependency file")
        ->type_name("FILE");
    cmd->add_flag("--json", options.json, "Print the build summary as JSON");
    cmd->add_flag("--keep-going", options.keepGoing, "Compile everything to report all errors");
    cmd->add_option("--compression-level", options.compressionLevel,
                    "zstd level of the pack's blobs, 1-22 (default 19; 3 writes faster, ~20% "
                    "bigger)")
        ->check(CLI::Range(1, 22));
    cmd->add_flag("-g,--debug-names", options.debugNames,
                  "Keep OpName/OpMemberName in the SPIR-V (bigger packs; for GPU debuggers)");
    addMaxVariants(*cmd, options);
    cmd->add_option("--cache-dir", options.cacheDirectory,
                    "Reuse and store compiled programs in this folder (ccache-like)")
        ->envname("VARC_CACHE_DIR")
        ->type_name("DIR");
    cmd->add_option("--shard", options.shard,
                    "Compile only shard K of N of the distinct programs into a partial pack "
                    "(join the N parts with `varc merge`)")
        ->type_name("K/N")
        ->check([](const std::string& text) {
            return driver::parseShardSpec(text)
                       ? std::string()
                       : "expected K/N with 1 <= K <= N <= " + std::to_string(driver::kMaxShards) +
                             ", got '" + text + "'";
        });
    cmd->add_option("--file-prefix-map", options.filePrefixMaps,
                    "Record source paths starting with OLD as starting with NEW (as GCC's "
                    "-ffile-prefix-map; other paths inside the project root are recorded "
                    "relative to it)")
        ->type_name("OLD=NEW")
        ->check([](const std::string& rule) {
            return includes::SourcePathMap().addRule(rule) ? std::string()
                                                           : "expected OLD=NEW, got '" + rule + "'";
        });
    addCacheUrls(*cmd, options);
    addDiagnosticsFormat(*cmd, options);
    addInputOptions(*cmd, options);
    cmd->callback([&options] { options.command = Command::Build; });
}

void addMerge(CLI::App& app, Options& options) {
    CLI::App* cmd = app.add_subcommand(
        "merge", "Join the partial packs of `varc build --shard K/N` into the whole build's pack");
    cmd->add_option("-o,--output", options.outputPath, "Pack file to write")->required();
    cmd->add_option("parts", options.inputs, "The N partial packs, in any order")
        ->required()
        ->type_name("PART");
    cmd->callback([&options] { options.command = Command::Merge; });
}

void addInfo(CLI::App& app, Options& options) {
    CLI::App* cmd =
        app.add_subcommand("info", "Describe a pack: shaders, passes, variants, programs");
    cmd->add_flag("--json", options.json, "Print JSON");
    cmd->add_option("pack", options.packPath, "Pack file")->required()->type_name("PACK");
    cmd->callback([&options] { options.command = Command::Info; });
}

void addExtract(CLI::App& app, Options& options) {
    CLI::App* cmd = app.add_subcommand("extract", "Write every program as .spv plus manifest.json");
    cmd->add_option("pack", options.packPath, "Pack file")->required()->type_name("PACK");
    cmd->add_option("-o,--output", options.outputPath, "Directory to write")
        ->required()
        ->type_name("DIR");
    cmd->callback([&options] { options.command = Command::Extract; });
}

void addLookup(CLI::App& app, Options& options) {
    CLI::App* cmd = app.add_subcommand("lookup", "Find the variant for keywords or a light");
    cmd->add_option("pack", options.packPath, "Pack file")->required()->type_name("PACK");
    cmd->add_option("--shader", options.lookupShader, "Shader name")->required()->type_name("NAME");
    cmd->add_option("--pass", options.lookupPass, "Pass index or LightMode")
        ->required()
        ->type_name("N|LIGHTMODE");
    auto* keywords =
        cmd->add_option("--keywords", options.lookupKeywords,
                        "Enabled keywords, space-separated (with --light: the material's)")
            ->type_name("\"A B\"");
    auto* light =
        cmd->add_option("--light", options.lookupLight, "Light type: directional, point or spot")
            ->type_name("TYPE");
    cmd->add_flag("--cookie", options.lookupCookie, "The light has a cookie")->needs(light);
    cmd->add_option("--shadows", options.lookupShadows, "none, hard or soft")
        ->type_name("MODE")
        ->needs(light);
    cmd->add_option("--vertex-lights", options.lookupVertexLights, "Point lights shaded per vertex")
        ->needs(light);
    cmd->add_flag("--hdr", options.lookupHdr, "The camera renders HDR")->needs(light);
    cmd->add_option("--policy", options.lookupPolicy, "exact, closest (default), first or strict")
        ->type_name("POLICY");
    cmd->add_flag("--json", options.json, "Print JSON");
    cmd->callback([&options, keywords, light] {
        options.command = Command::Lookup;
        if (keywords->count() == 0 && light->count() == 0) {
            throw CLI::RequiredError("lookup needs --keywords or --light");
        }
    });
}

void addExplain(CLI::App& app, Options& options) {
    CLI::App* cmd =
        app.add_subcommand("explain",
                           "Show which keywords change which stage's program in a pass, and why a "
                           "variant exists");
    cmd->add_option("--shader", options.lookupShader, "Shader name")->required()->type_name("NAME");
    cmd->add_option("--pass", options.lookupPass, "Pass index or LightMode")
        ->required()
        ->type_name("N|LIGHTMODE");
    cmd->add_option("--variant", options.explainVariant,
                    "Explain this variant: its keywords, space-separated (\"\" = none)")
        ->type_name("\"A B\"");
    cmd->add_option("--diff", options.explainDiff,
                    "Compare the pruned sources of two variants, stage by stage")
        ->expected(2)
        ->type_name("\"A B\" \"C D\"");
    cmd->add_option("-j,--jobs", options.jobs, "Worker threads (default: all cores)");
    cmd->add_flag("--json", options.json, "Print JSON");
    addMaxVariants(*cmd, options);
    addDiagnosticsFormat(*cmd, options);
    addInputOptions(*cmd, options);
    cmd->callback([&options] { options.command = Command::Explain; });
}

void addRender(CLI::App& app, Options& options) {
    CLI::App* cmd = app.add_subcommand("render", "Render a scene with pack variants on Vulkan");
    cmd->add_option("packs", options.packPaths, "Pack files")->required()->type_name("PACK");
    cmd->add_option("--scene", options.scenePath, "Scene JSON")->required()->type_name("FILE");
    cmd->add_option("-o,--output", options.outputPath, "PNG to write")
        ->required()
        ->type_name("FILE");
    cmd->add_option("--reference", options.referencePath,
                    "Also render the CPU reference to this PNG")
        ->type_name("FILE");
    cmd->add_option("--diff", options.diffPath, "Also compare and write the diff image here")
        ->type_name("FILE");
    cmd->add_option("--pipeline-cache", options.pipelineCachePath,
                    "VkPipelineCache file to load and save")
        ->type_name("FILE");
    cmd->callback([&options] { options.command = Command::Render; });
}

void addValidate(CLI::App& app, Options& options) {
    CLI::App* cmd =
        app.add_subcommand("validate", "Render every scene and compare with the CPU reference");
    cmd->add_option("--pack", options.packPaths, "Pack files (repeat)")
        ->required()
        ->type_name("PACK");
    cmd->add_option("--scenes", options.scenesDir, "Scene folder (default tests/scenes/forward)")
        ->type_name("DIR");
    cmd->add_option("--out", options.outputPath, "Folder for the PNGs (default validate-out)")
        ->type_name("DIR");
    cmd->add_flag("--properties", options.properties,
                  "Check metamorphic relations on generated scenes for every lit shader "
                  "(docs/PROPERTIES.md) instead of comparing scenes with the reference")
        ->excludes("--scenes");
    cmd->add_flag("--list-uncovered", options.list,
                  "Also list each variant no matching scene drew");
    cmd->add_option("--report", options.reportPath,
                    "Also write a self-contained HTML page of the images, variants and property "
                    "checks")
        ->type_name("FILE");
    cmd->add_option("--pipeline-cache", options.pipelineCachePath,
                    "VkPipelineCache file to load and save")
        ->type_name("FILE");
    cmd->callback([&options] { options.command = Command::Validate; });
}

// Hidden (no group, so neither --help nor the completion shows it): the build writes the man page
// and the bash completion from this very definition.
void addGenerate(CLI::App& app, Options& options) {
    CLI::App* cmd = app.add_subcommand("_generate", "Write the man page or the bash completion");
    cmd->group("");
    cmd->add_option("what", options.generateWhat, "man or bash-completion")
        ->required()
        ->check(CLI::IsMember({"man", "bash-completion"}));
    cmd->add_option("-o,--output", options.outputPath, "File to write")
        ->required()
        ->type_name("FILE");
    cmd->callback([&options] { options.command = Command::Generate; });
}

// The built-in include folder when --builtin-include-dir is not given: $VARC_BUILTIN_INCLUDE_DIR,
// else the installed or source-tree default.
std::string builtinIncludeDirUnlessGiven() {
    const char* env = std::getenv("VARC_BUILTIN_INCLUDE_DIR");
    return env && *env ? std::string(env) : defaultBuiltinIncludeDir();
}

// `varc --version`: the versions a pack records, then where the built-in includes are read.
std::string versionText() {
    std::string text;
    for (const pack::ToolVersion& tool : driver::toolchainVersions())
        text += tool.name + " " + tool.version + "\n";
    return text + "built-in includes: " + builtinIncludeDirUnlessGiven();
}

// Runs `_generate`: writes the man page or completion for |app| to options.outputPath.
int writeGenerated(const CLI::App& app, const Options& options, std::ostream& err) {
    std::string text = options.generateWhat == "man"
                           ? manPage(app, driver::toolchainVersions().front().version)
                           : bashCompletion(app);
    if (Status written = writeFileAtomically(options.outputPath, text); !written) {
        err << "varc: error: " << written.error().detail << "\n";
        return kExitFailure;
    }
    return kExitOk;
}

// CLI11 has no multi-letter short options, so -O0/-O/-Os become --optimization=<same>.
std::vector<std::string> normalizeArguments(int argc, const char* const* argv) {
    std::vector<std::string> args;
    for (int i = 1; i < argc; ++i) {
        std::string arg = argv[i];
        if (arg == "-O0" || arg == "-O" || arg == "-Os") arg = "--optimization=" + arg;
        args.push_back(arg);
    }
    std::reverse(args.begin(), args.end());  // CLI11 parses a reversed vector
    return args;
}

}  // namespace

std::optional<int> parseOptions(int argc, const char* const* argv, Options& options,
                                std::ostream& out, std::ostream& err) {
    CLI::App app{"varc: Unity-style shader variants to SPIR-V packs", "varc"};
    app.require_subcommand(1);
    app.set_version_flag("--version", versionText,
                         "Print the versions of varc, glslang and SPIRV-Tools and the built-in "
                         "include folder");
    app.footer(
        "Built-in includes: --builtin-include-dir, else $VARC_BUILTIN_INCLUDE_DIR, else "
        "<prefix>/share/varc/builtin beside an installed varc.");
    std::string growthText;
    addVariants(app, options);
    addLock(app, options);
    addCheck(app, options, growthText);
    addBuild(app, options);
    addMerge(app, options);
    addInfo(app, options);
    addExtract(app, options);
    addLookup(app, options);
    addExplain(app, options);
    addRender(app, options);
    addValidate(app, options);
    addGenerate(app, options);
    addCache(app, options);
    try {
        std::vector<std::string> args = normalizeArguments(argc, argv);
        app.parse(args);
    } catch (const CLI::ParseError& e) {
        int code = app.exit(e, out, err);
        return code == 0 ? kExitOk : kExitUsage;
    }
    if (!growthText.empty()) {
        options.maxGrowth = parseGrowth(growthText);
        if (!options.maxGrowth) {
            err << "varc: error: --max-growth expects N or N%, got '" << growthText << "'\n";
            return kExitUsage;
        }
    }
    if (options.cacheUrls.empty()) {
        if (const char* env = std::getenv("VARC_CACHE"))
            options.cacheUrls = cache::splitCacheList(env);
    }
    if (options.builtinIncludeDir.empty()) {
        options.builtinIncludeDir = builtinIncludeDirUnlessGiven();
    }
    if (options.command == Command::Generate) return writeGenerated(app, options, err);
    return std::nullopt;
}

}  // namespace varc::cli
