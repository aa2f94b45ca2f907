// SPDX-License-Identifier: Apache-2.0
// The `varc` command-line tool as a library: option parsing, then one command.
#include "varc/cli/Cli.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <ostream>
#include <sstream>

#include "varc/cli/BuildReport.h"
#include "varc/cli/CacheCommands.h"
#include "varc/cli/DiagnosticOutput.h"
#include "varc/cli/ExplainReport.h"
#include "varc/cli/ExplainText.h"
#include "varc/cli/LockCheck.h"
#include "varc/cli/LockFile.h"
#include "varc/cli/Options.h"
#include "varc/cli/PackCommands.h"
#include "varc/cli/RenderCommands.h"
#include "varc/cli/ShaderInputs.h"
#include "varc/cli/VariantReport.h"
#include "varc/core/AsciiCase.h"
#include "varc/core/AtomicFile.h"
#include "varc/driver/CompileDriver.h"
#include "varc/driver/Depfile.h"
#include "varc/driver/PackAssembler.h"
#include "varc/frontend/ShaderLoader.h"
#include "varc/frontend/VariantLimit.h"
#include "varc/pack/PartialPack.h"
#include "varc/packwriter/PackWriter.h"

namespace varc::cli {

namespace {

// State shared by the commands: the files read, the diagnostics reported so far and where they
// are written.
struct Session {
    explicit Session(const Options& options, std::ostream& err)
        : output(options.diagnosticsFormat, sourceMap, err) {}

    includes::DiskFileSystem fileSystem;
    includes::SourceMap sourceMap;
    DiagnosticList diagnostics;
    DiagnosticOutput output;
    size_t printed = 0;  // diagnostics already written

    // Writes the diagnostics reported since the last call, as found by |rule|.
    void printNew(DiagnosticRule rule) {
        const std::vector<Diagnostic>& all = diagnostics.diagnostics();
        output.print(
            std::vector<Diagnostic>(all.begin() + static_cast<std::ptrdiff_t>(printed), all.end()),
            rule);
        printed = all.size();
    }
};

includes::IncludeOptions includeOptions(const Options& options) {
    includes::IncludeOptions result;
    result.includeDirs = options.includeDirs;
    result.builtinDir = options.builtinIncludeDir;
    result.projectRoot = options.projectRoot;
    return result;
}

// How the pack records source paths: relative to --project-root (default: the current folder),
// with the --file-prefix-map rules (checked when parsed).
includes::SourcePathMap sourcePathMap(const Options& options) {
    std::error_code error;
    std::filesystem::path root = options.projectRoot.empty()
                                     ? std::filesystem::current_path(error)
                                     : std::filesystem::absolute(options.projectRoot, error);
    includes::SourcePathMap map(error ? std::string() : root.lexically_normal().string());
    for (const std::string& rule : options.filePrefixMaps) map.addRule(rule);
    return map;
}

// Loads every input shader; false when any failed (diagnostics are in |session|).
bool loadAll(const Options& options, Session& session,
             std::vector<frontend::LoadedShader>& shaders) {
    std::vector<std::string> files = findShaderFiles(options.inputs, session.diagnostics);
    includes::IncludeOptions include = includeOptions(options);
    // UsePass and Fallback find other shaders among the inputs, then under the include folders.
    DiagnosticList searchErrors;  // an unreadable include folder is reported by the includes
    frontend::ShaderCatalog catalog(session.fileSystem, session.sourceMap, files,
                                    findShaderFiles(options.includeDirs, searchErrors),
                                    include.builtinDir);
    for (const std::string& file : files) {
        auto shader = frontend::loadShader(file, session.fileSystem, session.sourceMap, include,
                                           session.diagnostics, &catalog);
        if (shader) shaders.push_back(std::move(*shader));
    }
    return !session.diagnostics.hasErrors();
}

// --max-variants for every pass of |shaders|: false (errors in |session|) when one has more.
bool checkVariantLimits(const std::vector<frontend::LoadedShader>& shaders, const Options& options,
                        Session& session) {
    bool ok = true;
    for (const frontend::LoadedShader& shader : shaders) {
        for (const frontend::LoadedPass& pass : shader.passes) {
            ok = frontend::checkVariantLimit(shader, pass, options.maxVariants,
                                             session.diagnostics) &&
                 ok;
        }
    }
    return ok;
}

int runVariants(const Options& options, Session& session, std::ostream& out) {
    std::vector<frontend::LoadedShader> shaders;
    bool ok = loadAll(options, session, shaders);
    if (ok && options.list) ok = checkVariantLimits(shaders, options, session);
    session.printNew(DiagnosticRule::Input);
    if (!ok) return kExitFailure;
    if (options.json) {
        out << variantsJson(shaders, options.list).dump() << "\n";
    } else {
        printVariantsText(shaders, session.sourceMap, options.list, out);
    }
    return kExitOk;
}

int runLock(const Options& options, Session& session, std::ostream& out) {
    std::vector<frontend::LoadedShader> shaders;
    bool ok = loadAll(options, session, shaders);
    // A lock records what builds: a pass that cannot be built does not belong in one.
    if (ok) ok = checkVariantLimits(shaders, options, session);
    session.printNew(DiagnosticRule::Input);
    if (!ok) return kExitFailure;
    std::string lockDir = std::filesystem::path(options.lockPath).parent_path().string();
    LockFile lock = makeLock(shaders, lockDir);
    Status written = writeFileAtomically(options.lockPath, serializeLock(lock));
    if (!written) {
        session.output.error(written.error().detail);
        return kExitFailure;
    }
    out << "wrote " << options.lockPath << ": " << lock.shaders.size() << " shaders\n";
    return kExitOk;
}

std::optional<LockFile> readLock(const std::string& path, Session& session) {
    auto text = session.fileSystem.read(path);
    if (!text) {
        session.output.error("cannot read lock file '" + path + "'");
        return std::nullopt;
    }
    Result<LockFile> lock = parseLock(*text, path);
    if (!lock) {
        session.output.error(lock.error().detail);
        return std::nullopt;
    }
    return std::move(lock).value();
}

int runCheck(const Options& options, Session& session, std::ostream& out) {
    std::optional<LockFile> lock = readLock(options.lockPath, session);
    if (!lock) return kExitUsage;
    std::vector<frontend::LoadedShader> shaders;
    if (!loadAll(options, session, shaders)) {
        session.printNew(DiagnosticRule::Input);
        return kExitUsage;
    }
    session.printNew(DiagnosticRule::Input);  // warnings
    DiagnosticList findings;
    bool passed = checkAgainstLock(*lock, shaders, {options.maxGrowth, options.budget}, findings);
    session.output.print(findings.diagnostics(), DiagnosticRule::Lock);
    if (!passed) {
        session.output.summary("varc check: variant counts differ from " + options.lockPath +
                               "; if the change is intended, run `varc lock -o " +
                               options.lockPath + "`");
        return kExitFailure;
    }
    out << "varc check: " << shaders.size() << " shaders match " << options.lockPath << "\n";
    return kExitOk;
}

// Raw bytes count every variant's stages as if stored separately; unique counts each module once.
// A shard's placeholders are skipped: they stand for modules another shard builds.
PackSizes measureSpirv(const driver::BuildOutput& build) {
    PackSizes sizes;
    auto isModule = [&](uint32_t program) {
        return program != pack::kNoProgram &&
               !pack::isPlaceholderSpirv(build.programs[program].spirv);
    };
    for (uint32_t program = 0; program < build.programs.size(); ++program) {
        if (!isModule(program)) continue;
        ++sizes.modules;
        sizes.uniqueSpirvBytes += build.programs[program].spirv.size() * sizeof(uint32_t);
    }
    for (const driver::CompiledPass& pass : build.passes) {
        for (const pack::PackVariant& variant : pass.variants) {
            for (uint32_t program : variant.programs) {
                if (!isModule(program)) continue;
                sizes.rawSpirvBytes += build.programs[program].spirv.size() * sizeof(uint32_t);
            }
        }
    }
    return sizes;
}

std::vector<std::string> buildDependencies(const std::vector<frontend::LoadedShader>& shaders) {
    std::vector<std::string> dependencies;
    for (const frontend::LoadedShader& shader : shaders) {
        dependencies.push_back(shader.path);
        for (const frontend::LoadedPass& pass : shader.passes) {
            dependencies.insert(dependencies.end(), pass.source.dependencies.begin(),
                                pass.source.dependencies.end());
        }
    }
    return dependencies;
}

// Prints "[done/total] compiling" on a terminal, at most ~20 times a second.
std::function<void(size_t, size_t)> progressPrinter(std::ostream& err) {
    if (!::isatty(STDERR_FILENO)) return {};
    auto state = std::make_shared<std::pair<std::mutex, std::chrono::steady_clock::time_point>>();
    return [state, &err](size_t done, size_t total) {
        std::lock_guard<std::mutex> lock(state->first);
        auto now = std::chrono::steady_clock::now();
        if (done != total && now - state->second < std::chrono::milliseconds(50)) return;
        state->second = now;
        err << "\r[" << done << "/" << total << "] compiling" << (done == total ? "\n" : "")
            << std::flush;
    };
}

int runBuild(const Options& options, Session& session, std::ostream& out, std::ostream& err) {
    auto start = std::chrono::steady_clock::now();
    std::vector<frontend::LoadedShader> shaders;
    if (!loadAll(options, session, shaders)) {
        session.printNew(DiagnosticRule::Input);
        return kExitFailure;
    }
    session.printNew(DiagnosticRule::Input);  // warnings
    Result<std::shared_ptr<cache::CacheChain>> cacheLevels = openCacheLevels(options);
    if (!cacheLevels) {
        session.output.error(cacheLevels.error().detail);
        return kExitUsage;
    }
    driver::BuildOptions buildOptions;
    buildOptions.cache = *cacheLevels;
    buildOptions.optimization = *driver::parseOptimizationLevel(options.optimization);
    buildOptions.jobs = options.jobs;
    buildOptions.keepGoing = options.keepGoing;
    buildOptions.maxVariantsPerPass = options.maxVariants;
    buildOptions.debugNames = options.debugNames;
    if (!session.output.isDocument()) buildOptions.progress = progressPrinter(err);
    if (!options.shard.empty()) buildOptions.shard = *driver::parseShardSpec(options.shard);
    buildOptions.sourcePaths = sourcePathMap(options);
    auto build =
        driver::buildPrograms(shaders, session.sourceMap, buildOptions, session.diagnostics);
    session.printNew(DiagnosticRule::Compile);
    if (!build) {
        session.output.summary("varc build: failed; " + options.outputPath + " was not written");
        return kExitFailure;
    }
    PackSizes sizes = measureSpirv(*build);
    std::optional<pack::PackContents> contents;
    if (driver::checkStageInterfaces(shaders, *build, session.diagnostics)) {
        // -g changes the SPIR-V, so it is part of what parts of one sharded build must share.
        std::string fingerprint =
            "optimization=" + options.optimization + (options.debugNames ? " -g" : "");
        contents = driver::assemblePack(shaders, *build, session.sourceMap,
                                        buildOptions.sourcePaths, fingerprint, session.diagnostics);
    }
    if (contents && !buildOptions.shard.whole()) {
        contents->toolchain.push_back(
            {std::string(pack::kShardTool),
             buildOptions.shard.text() + " level=" + std::to_string(options.compressionLevel)});
    }
    if (!contents) {
        session.printNew(DiagnosticRule::Compile);
        session.output.summary("varc build: failed; " + options.outputPath + " was not written");
        return kExitFailure;
    }
    session.printNew(DiagnosticRule::Compile);  // warnings
    packwriter::PackWriteStats stats;
    packwriter::PackWriteOptions writeOptions;
    writeOptions.compressionLevel = options.compressionLevel;
    Status written = packwriter::writePack(options.outputPath, *contents, writeOptions, &stats);
    if (!written) {
        session.output.error(written.error().detail);
        return kExitFailure;
    }
    sizes.packBytes = stats.packBytes;
    if (!options.depfilePath.empty()) {
        Status depfile = writeFileAtomically(
            options.depfilePath,
            driver::makeDepfile(options.outputPath, buildDependencies(shaders)));
        if (!depfile) {
            session.output.error(depfile.error().detail);
            return kExitFailure;
        }
    }
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (options.json) {
        nlohmann::ordered_json report = buildReportJson(shaders, *build, sizes, seconds);
        if (!buildOptions.shard.whole()) {
            report["shard"] = {{"shard", buildOptions.shard.text()},
                               {"compiled", build->compiledSources},
                               {"items", build->items - build->otherShardItems},
                               {"left_to_other_shards", build->otherShardItems}};
        }
        out << report.dump() << "\n";
    } else {
        printBuildReport(shaders, *build, sizes, seconds, out);
        if (!buildOptions.shard.whole()) {
            out << "Shard " << buildOptions.shard.text() << ": built "
                << build->items - build->otherShardItems << " of " << build->items
                << " variant stages (" << build->compiledSources
                << " distinct programs); the partial pack holds placeholders for the others "
                << "(join the parts with `varc merge`)\n";
        }
        out << "wrote " << options.outputPath << "\n";
    }
    return kExitOk;
}

// The pass of |shader| that --pass names: its index, else its LightMode; -1 when none does.
int findLoadedPass(const frontend::LoadedShader& shader, const std::string& selector) {
    for (size_t p = 0; p < shader.passes.size(); ++p) {
        const frontend::LoadedPass& pass = shader.passes[p];
        if (std::to_string(pass.index) == selector ||
            (!pass.pass->lightMode().empty() &&
             equalsIgnoreAsciiCase(pass.pass->lightMode(), selector))) {
            return static_cast<int>(p);
        }
    }
    return -1;
}

std::vector<std::string> splitKeywords(const std::string& text) {
    std::vector<std::string> words;
    std::istringstream in(text);
    for (std::string word; in >> word;) words.push_back(word);
    return words;
}

// The variant of |compiled| with exactly |keywords| (declared ones), or an error reported.
std::optional<size_t> explainedVariant(const frontend::LoadedPass& pass,
                                       const driver::CompiledPass& compiled,
                                       const std::string& keywords, Session& session) {
    std::optional<size_t> variant = findVariant(pass, compiled, splitKeywords(keywords));
    if (!variant) {
        session.output.error("no variant of this pass has exactly the keywords \"" + keywords +
                             "\" (see `varc variants --list`)");
    }
    return variant;
}

int runExplain(const Options& options, Session& session, std::ostream& out) {
    std::vector<frontend::LoadedShader> shaders;
    bool loaded = loadAll(options, session, shaders);
    session.printNew(DiagnosticRule::Input);
    if (!loaded) return kExitFailure;
    auto shader = std::find_if(shaders.begin(), shaders.end(), [&](const auto& candidate) {
        return candidate.ast.name == options.lookupShader;
    });
    if (shader == shaders.end()) {
        session.output.error("no shader named \"" + options.lookupShader + "\" in the inputs");
        return kExitFailure;
    }
    int passPosition = findLoadedPass(*shader, options.lookupPass);
    if (passPosition < 0) {
        session.output.error("shader \"" + options.lookupShader + "\" has no pass '" +
                             options.lookupPass + "' with a program");
        return kExitFailure;
    }
    std::vector<frontend::LoadedShader> one;
    one.push_back(std::move(*shader));  // LoadedPass::pass stays valid: the AST moves whole
    driver::BuildOptions buildOptions;
    buildOptions.jobs = options.jobs;
    buildOptions.maxVariantsPerPass = options.maxVariants;
    buildOptions.keepPrunedSources = true;
    auto build = driver::buildPrograms(one, session.sourceMap, buildOptions, session.diagnostics);
    session.printNew(DiagnosticRule::Compile);
    if (!build) return kExitFailure;
    auto compiled = std::find_if(build->passes.begin(), build->passes.end(), [&](const auto& p) {
        return p.passIndex == static_cast<size_t>(passPosition);
    });
    if (compiled == build->passes.end()) {
        session.output.error("pass '" + options.lookupPass + "' is not built for Vulkan");
        return kExitFailure;
    }
    const frontend::LoadedPass& pass = one.front().passes[static_cast<size_t>(passPosition)];
    ExplainRequest request{&one.front(), &pass, &*compiled, &*build, std::nullopt, std::nullopt};
    if (options.explainVariant) {
        request.variant = explainedVariant(pass, *compiled, *options.explainVariant, session);
        if (!request.variant) return kExitFailure;
    }
    if (options.explainDiff.size() == 2) {
        auto a = explainedVariant(pass, *compiled, options.explainDiff[0], session);
        auto b = explainedVariant(pass, *compiled, options.explainDiff[1], session);
        if (!a || !b) return kExitFailure;
        request.diff = std::make_pair(*a, *b);
    }
    nlohmann::ordered_json report = explainJson(request, session.sourceMap);
    if (options.json) {
        out << report.dump() << "\n";
    } else {
        printExplainText(report, out);
    }
    return kExitOk;
}

}  // namespace

int runCli(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
    Options options;
    if (auto exitCode = parseOptions(argc, argv, options, out, err)) return *exitCode;
    Session session(options, err);
    // The shader commands end by writing the JSON or SARIF document, whatever path they took.
    auto shaderCommand = [&session](int exitCode) {
        session.output.finish();
        return exitCode;
    };
    switch (options.command) {
        case Command::Variants:
            return shaderCommand(runVariants(options, session, out));
        case Command::Lock:
            return shaderCommand(runLock(options, session, out));
        case Command::Check:
            return shaderCommand(runCheck(options, session, out));
        case Command::Build:
            return shaderCommand(runBuild(options, session, out, err));
        case Command::Merge:
            return runMerge(options, out, err);
        case Command::Info:
            return runInfo(options, out, err);
        case Command::Extract:
            return runExtract(options, out, err);
        case Command::Lookup:
            return runLookup(options, out, err);
        case Command::Render:
            return runRender(options, out, err);
        case Command::Validate:
            return runValidate(options, out, err);
        case Command::CacheStats:
            return runCacheStats(options, out, err);
        case Command::CacheClear:
            return runCacheClear(options, out, err);
        case Command::Explain:
            return shaderCommand(runExplain(options, session, out));
        case Command::Generate:  // parseOptions wrote it
        case Command::None:
            break;
    }
    err << "varc: error: no command given\n";
    return kExitUsage;
}

}  // namespace varc::cli
