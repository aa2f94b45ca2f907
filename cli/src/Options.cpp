// SPDX-License-Identifier: Apache-2.0
// Command-line parsing for `varc`, through CLI11: the application, the flags several subcommands
// share, and the decoding that ends a parse.
#include "varc/cli/Options.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdlib>
#include <map>
#include <ostream>

#include "BashCompletion.h"
#include "BuiltinIncludeDir.h"
#include "ManPage.h"
#include "OptionDefinitions.h"
#include "varc/core/AtomicFile.h"
#include "varc/driver/PackAssembler.h"

namespace varc::cli {

Error usageError(std::string detail) {
    return makeError(ErrorCode::InvalidInput, std::move(detail));
}

void addInputOptions(CLI::App& command, ShaderInputOptions& input) {
    // Repeatable options take one value each, so they never swallow the PATH arguments (which
    // are optional with --project).
    command.add_option("-I,--include-dir", input.includeDirs, "Add an include directory")
        ->allow_extra_args(false)
        ->type_name("DIR");
    command
        .add_option("--project-root", input.projectRoot,
                    "Folder that #include \"Assets/...\" paths start from (default: the nearest "
                    "folder above the shader that has them)")
        ->type_name("DIR");
    command
        .add_option("--builtin-include-dir", input.builtinIncludeDir,
                    "Override the built-in include directory")
        ->type_name("DIR");
    command
        .add_option("--project", input.projectDir,
                    "A Unity project folder: its shaders, and the variants its materials, "
                    "Graphics Settings and variant collections select (docs/PROJECTS.md)")
        ->type_name("DIR");
    command
        .add_option("--project-shaders", input.projectShaders,
                    "Read the project's shader and include files from this folder (same "
                    "relative paths) when the project folder holds only its assets; repeat "
                    "for several")
        ->allow_extra_args(false)
        ->type_name("DIR");
    command
        .add_option("--builtin-shaders", input.builtinShaderDirs,
                    "Folder with Unity's built-in shaders, for materials that name one by file ID "
                    "(Standard); repeat for several")
        ->allow_extra_args(false)
        ->type_name("DIR");
    command
        .add_option("--strip-rules", input.stripRulesPath,
                    "Remove variants by shader, pass, stage and keywords (a YAML file, "
                    "docs/PROJECTS.md); each rule reports what it removed")
        ->type_name("FILE");
    command
        .add_option("--usage-log", input.usageLogs,
                    "Also build what a runtime session recorded (`varc render --usage-log`), as a "
                    "variant collection; repeat for several")
        ->allow_extra_args(false)
        ->type_name("FILE");
    command.add_option("paths", input.inputs,
                       "Shader files, or directories to search (optional with --project)")
        ->type_name("PATH");
}

void addMaxVariants(CLI::App& command, uint64_t& maxVariants) {
    command
        .add_option("--max-variants", maxVariants,
                    "Refuse a pass with more variants than N before enumerating them (default " +
                        std::to_string(frontend::kDefaultMaxVariantsPerPass) + ")")
        ->type_name("N")
        ->check(CLI::PositiveNumber);
}

void addJobs(CLI::App& command, unsigned& jobs) {
    command.add_option("-j,--jobs", jobs, "Worker threads (default: all cores)");
}

void addDiagnosticsFormat(CLI::App& command, ShaderInputOptions& input) {
    static const std::map<std::string, DiagnosticsFormat> kFormats = {
        {"clang", DiagnosticsFormat::Clang},
        {"json", DiagnosticsFormat::Json},
        {"github", DiagnosticsFormat::Github},
        {"sarif", DiagnosticsFormat::Sarif}};
    command
        .add_option_function<std::string>(
            "--diagnostics-format",
            [&input](const std::string& name) { input.diagnosticsFormat = kFormats.at(name); },
            "How errors and warnings are written to standard error: clang (default), json, "
            "github (Actions annotations) or sarif (SARIF 2.1.0)")
        ->type_name("FORMAT")
        ->check(CLI::IsMember({"clang", "json", "github", "sarif"}));
}

void addCacheUrls(CLI::App& command, std::vector<std::string>& urls) {
    command
        .add_option("--cache", urls,
                    "Program cache level, in order (repeat): file:DIR or "
                    "redis://HOST[:PORT][/DB], each with |read-only, |prefix=, |ttl=, "
                    "|connect-timeout=MS, |operation-timeout=MS (default: $VARC_CACHE)")
        ->allow_extra_args(false)
        ->type_name("URL")
        ->allow_extra_args(false);
}

namespace {

// The built-in include folder when --builtin-include-dir is not given: $VARC_BUILTIN_INCLUDE_DIR,
// else the installed or source-tree default.
std::string builtinIncludeDirUnlessGiven() {
    const char* env = std::getenv("VARC_BUILTIN_INCLUDE_DIR");
    return env && *env ? std::string(env) : defaultBuiltinIncludeDir();
}

}  // namespace

Status finishInput(ShaderInputOptions& input) {
    if (input.inputs.empty() && input.projectDir.empty()) {
        return usageError("no shaders to read: give shader files or folders (PATH...), or a "
                          "Unity project with --project DIR");
    }
    if (!input.projectShaders.empty() && input.projectDir.empty()) {
        return usageError("--project-shaders needs --project DIR");
    }
    if (input.builtinIncludeDir.empty()) input.builtinIncludeDir = builtinIncludeDirUnlessGiven();
    return Ok{};
}

Result<std::vector<cache::CacheSpec>> cacheLevelsOf(const std::string& directory,
                                                    const std::vector<std::string>& urls) {
    std::vector<cache::CacheSpec> levels;
    if (!directory.empty()) levels.push_back(cache::directoryCacheSpec(directory));
    std::vector<std::string> named = urls;
    if (named.empty()) {
        if (const char* env = std::getenv("VARC_CACHE")) named = cache::splitCacheList(env);
    }
    for (const std::string& url : named) {
        Result<cache::CacheSpec> spec = cache::parseCacheSpec(url);
        if (!spec) return usageError(spec.error().detail);
        levels.push_back(std::move(*spec));
    }
    return levels;
}

namespace {

// `varc --version`: the versions a pack records, then where the built-in includes are read.
std::string versionText() {
    std::string text;
    for (const pack::ToolVersion& tool : driver::toolchainVersions())
        text += tool.name + " " + tool.version + "\n";
    return text + "built-in includes: " + builtinIncludeDirUnlessGiven();
}

// Hidden (no group, so neither --help nor the completion shows it): the build writes the man page
// and the bash completion from this very definition.
void addGenerate(CLI::App& app, ParseState& state) {
    CLI::App* cmd = app.add_subcommand("_generate", "Write the man page or the bash completion");
    cmd->group("");
    auto what = std::make_shared<std::string>();
    cmd->add_option("what", *what, "man or bash-completion")
        ->required()
        ->check(CLI::IsMember({"man", "bash-completion"}));
    cmd->add_option("-o,--output", state.generateOutput, "File to write")
        ->required()
        ->type_name("FILE");
    cmd->callback([&state, what] { state.generateWhat = *what; });
}

// Runs `_generate`: writes the man page or completion for |app| to the -o file.
int writeGenerated(const CLI::App& app, const ParseState& state, std::ostream& err) {
    std::string text = *state.generateWhat == "man"
                           ? manPage(app, driver::toolchainVersions().front().version)
                           : bashCompletion(app);
    if (Status written = writeFileAtomically(state.generateOutput, text); !written) {
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

// The whole command-line definition; |state| receives what the chosen subcommand parsed.
void defineApp(CLI::App& app, ParseState& state) {
    app.require_subcommand(1);
    app.set_version_flag("--version", versionText,
                         "Print the versions of varc, glslang and SPIRV-Tools and the built-in "
                         "include folder");
    app.footer(
        "Built-in includes: --builtin-include-dir, else $VARC_BUILTIN_INCLUDE_DIR, else "
        "<prefix>/share/varc/builtin beside an installed varc.");
    addVariants(app, state);
    addLock(app, state);
    addCheck(app, state);
    addBuild(app, state);
    addMerge(app, state);
    addInfo(app, state);
    addExtract(app, state);
    addLookup(app, state);
    addExplain(app, state);
    addRender(app, state);
    addValidate(app, state);
    addGenerate(app, state);
    addCache(app, state);
}

}  // namespace

ParsedCommandLine parseCommandLine(int argc, const char* const* argv, std::ostream& out,
                                   std::ostream& err) {
    CLI::App app{"varc: Unity-style shader variants to SPIR-V packs", "varc"};
    ParseState state;
    defineApp(app, state);
    ParsedCommandLine parsed;
    try {
        std::vector<std::string> args = normalizeArguments(argc, argv);
        app.parse(args);
    } catch (const CLI::ParseError& e) {
        parsed.exitCode = app.exit(e, out, err) == 0 ? kExitOk : kExitUsage;
        return parsed;
    }
    if (state.generateWhat) {
        parsed.exitCode = writeGenerated(app, state, err);
        return parsed;
    }
    if (!state.finish) {  // require_subcommand(1) makes this unreachable
        err << "varc: error: no command given\n";
        parsed.exitCode = kExitUsage;
        return parsed;
    }
    Result<CommandOptions> command = state.finish();
    if (!command) {
        err << "varc: error: " << command.error().detail << "\n";
        parsed.exitCode = kExitUsage;
        return parsed;
    }
    parsed.command = std::move(*command);
    return parsed;
}

}  // namespace varc::cli
