// SPDX-License-Identifier: Apache-2.0
// The `varc` command-line tool as a library: option parsing, then one command.
#include "varc/cli/Cli.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <memory>
#include <mutex>
#include <optional>
#include <ostream>
#include <set>
#include <sstream>

#include "Session.h"
#include "varc/cli/BuildReport.h"
#include "varc/cli/CacheCommands.h"
#include "varc/cli/DiagnosticOutput.h"
#include "varc/cli/DirectMode.h"
#include "varc/cli/DriverOptions.h"
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
#include "varc/driver/OptimizerWorker.h"
#include "varc/driver/PackAssembler.h"
#include "varc/frontend/ShaderLoader.h"
#include "varc/frontend/VariantLimit.h"
#include "varc/pack/PartialPack.h"
#include "varc/packwriter/PackWriter.h"

namespace varc::cli {

namespace {

// --max-variants for every pass of |shaders|: false (errors in |session|) when one has more.
bool checkVariantLimits(const std::vector<frontend::LoadedShader>& shaders, uint64_t maxVariants,
                        Session& session) {
    bool ok = true;
    for (const frontend::LoadedShader& shader : shaders) {
        for (const frontend::LoadedPass& pass : shader.passes) {
            ok = frontend::checkVariantLimit(shader, pass, maxVariants, session.diagnostics) && ok;
        }
    }
    return ok;
}

int runVariants(const VariantsOptions& options, Session& session, std::ostream& out) {
    std::vector<frontend::LoadedShader> shaders;
    bool ok = loadAll(options.input, session, shaders, options.maxVariants);
    if (ok && options.list) ok = checkVariantLimits(shaders, options.maxVariants, session);
    session.printNew(DiagnosticRule::Input);
    if (!ok) return kExitFailure;
    if (options.json) {
        nlohmann::ordered_json json = variantsJson(shaders, options.list);
        if (session.project && !session.project->root.empty())
            json["project"] = projectJson(*session.project);
        out << json.dump() << "\n";
    } else {
        if (session.project && !session.project->root.empty())
            out << projectSummary(*session.project) << "\n";
        printVariantsText(shaders, session.sourceMap, options.list, out);
    }
    return kExitOk;
}

int runLock(const LockOptions& options, Session& session, std::ostream& out) {
    std::vector<frontend::LoadedShader> shaders;
    bool ok = loadAll(options.input, session, shaders, options.maxVariants);
    // A lock records what builds: a pass that cannot be built does not belong in one.
    if (ok) ok = checkVariantLimits(shaders, options.maxVariants, session);
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

int runCheck(const CheckOptions& options, Session& session, std::ostream& out) {
    std::optional<LockFile> lock = readLock(options.lockPath, session);
    if (!lock) return kExitUsage;
    std::vector<frontend::LoadedShader> shaders;
    if (!loadAll(options.input, session, shaders)) {
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

// The pack of a finished build, assembled (nullopt after the errors are reported). A shard's
// partial pack records which shard it is and the compression level every part must share.
std::optional<pack::PackContents> assembleBuiltPack(
    const BuildCommandOptions& options, const driver::BuildOptions& buildOptions,
    const std::vector<frontend::LoadedShader>& shaders, const driver::BuildOutput& build,
    Session& session) {
    std::optional<pack::PackContents> contents;
    if (driver::checkStageInterfaces(shaders, build, session.diagnostics)) {
        // -g changes the SPIR-V, so it is part of what parts of one sharded build must share.
        std::string fingerprint = "optimization=" + optimizationFlag(options.compile.optimization) +
                                  (options.compile.debugNames ? " -g" : "");
        contents = driver::assemblePack(shaders, build, session.sourceMap, buildOptions.sourcePaths,
                                        fingerprint, session.diagnostics);
    }
    if (contents && !buildOptions.shard.whole()) {
        contents->toolchain.push_back(
            {std::string(pack::kShardTool),
             buildOptions.shard.text() + " level=" + std::to_string(options.compressionLevel)});
    }
    session.printNew(DiagnosticRule::Compile);  // errors, or warnings
    if (!contents) {
        session.output.summary("varc build: failed; " + options.outputPath + " was not written");
    }
    return contents;
}

// Writes |pack| to -o and the --depfile listing |dependencies|; false after reporting why not.
bool writeOutputs(const BuildCommandOptions& options, const std::string& pack,
                  const std::vector<std::string>& dependencies, Session& session) {
    Status written = writeFileAtomically(options.outputPath, pack);
    if (written && !options.depfilePath.empty()) {
        written = writeFileAtomically(options.depfilePath,
                                      driver::makeDepfile(options.outputPath, dependencies));
    }
    if (!written) session.output.error(written.error().detail);
    return static_cast<bool>(written);
}

// Writes the pack (its bytes are left in |pack|) and the --depfile; false after reporting why
// not.
bool writeBuildFiles(const BuildCommandOptions& options, const pack::PackContents& contents,
                     const std::vector<frontend::LoadedShader>& shaders, PackSizes& sizes,
                     Session& session, std::string& pack) {
    packwriter::PackWriteStats stats;
    packwriter::PackWriteOptions writeOptions;
    writeOptions.compressionLevel = options.compressionLevel;
    pack = packwriter::serializePack(contents, writeOptions, &stats);
    sizes.packBytes = stats.packBytes;
    return writeOutputs(options, pack, buildDependencies(shaders), session);
}

// A direct hit: the recorded pack and depfile written, and the summary.
int finishDirectHit(const BuildCommandOptions& options, DirectMode& direct, const std::string& pack,
                    std::chrono::steady_clock::time_point start, Session& session,
                    std::ostream& out) {
    if (!writeOutputs(options, pack, direct.manifest().dependencies, session)) {
        return kExitFailure;
    }
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (options.json) {
        nlohmann::ordered_json report = {{"direct", directJson(direct.outcome())},
                                         {"bytes", {{"pack", pack.size()}}},
                                         {"seconds", seconds}};
        out << report.dump() << "\n";
        return kExitOk;
    }
    std::ostringstream time;
    time << std::fixed << std::setprecision(3) << seconds;
    out << "varc build: " << directSummaryLine(direct.outcome()) << " in " << time.str()
        << " s; pack " << pack.size() << " bytes\nwrote " << options.outputPath << "\n";
    return kExitOk;
}

// Stores the pack and manifest of a build direct mode missed; a build that reported warnings
// is not recorded, so a later build reports them again.
void recordDirect(DirectMode& direct, const std::string& pack,
                  const std::vector<frontend::LoadedShader>& shaders, Session& session) {
    if (!session.diagnostics.diagnostics().empty()) {
        direct.outcome().notRecorded = "the build reported diagnostics";
        return;
    }
    direct.record(pack, buildDependencies(shaders), session.fileSystem.queries());
}

// The summary of a written build: JSON, or the report for people.
void printBuildSummary(const BuildCommandOptions& options, const driver::ShardSpec& shard,
                       const std::vector<frontend::LoadedShader>& shaders,
                       const driver::BuildOutput& build, const PackSizes& sizes, double seconds,
                       const DirectOutcome* direct, std::ostream& out) {
    if (options.json) {
        nlohmann::ordered_json report = buildReportJson(shaders, build, sizes, seconds);
        if (direct) report["direct"] = directJson(*direct);
        if (!shard.whole()) {
            report["shard"] = {{"shard", shard.text()},
                               {"compiled", build.compiledSources},
                               {"items", build.items - build.otherShardItems},
                               {"left_to_other_shards", build.otherShardItems}};
        }
        out << report.dump() << "\n";
        return;
    }
    printBuildReport(shaders, build, sizes, seconds, out);
    if (!shard.whole()) {
        out << "Shard " << shard.text() << ": built " << build.items - build.otherShardItems
            << " of " << build.items << " variant stages (" << build.compiledSources
            << " distinct programs); the partial pack holds placeholders for the others "
            << "(join the parts with `varc merge`)\n";
    }
    if (direct) out << directSummaryLine(*direct) << "\n";
    out << "wrote " << options.outputPath << "\n";
}

int runBuild(const BuildCommandOptions& options, Session& session, std::ostream& out,
             std::ostream& err) {
    auto start = std::chrono::steady_clock::now();
    driver::BuildOptions buildOptions = toBuildOptions(options.compile, options.input);
    std::optional<DirectMode> direct = DirectMode::open(options, buildOptions.cache, session.disk);
    if (direct) {
        if (std::optional<std::string> pack = direct->findPack(session.disk))
            return finishDirectHit(options, *direct, *pack, start, session, out);
        session.fileSystem.startRecording();
    }
    std::vector<frontend::LoadedShader> shaders;
    bool loaded = loadAll(options.input, session, shaders, options.compile.maxVariants);
    session.printNew(DiagnosticRule::Input);  // errors, or warnings
    if (!loaded) return kExitFailure;
    if (!session.output.isDocument()) buildOptions.progress = progressPrinter(err);
    auto build =
        driver::buildPrograms(shaders, session.sourceMap, buildOptions, session.diagnostics);
    session.printNew(DiagnosticRule::Compile);
    if (!build) {
        session.output.summary("varc build: failed; " + options.outputPath + " was not written");
        return kExitFailure;
    }
    PackSizes sizes = measureSpirv(*build);
    std::optional<pack::PackContents> contents =
        assembleBuiltPack(options, buildOptions, shaders, *build, session);
    std::string pack;
    if (!contents || !writeBuildFiles(options, *contents, shaders, sizes, session, pack)) {
        return kExitFailure;
    }
    if (direct) recordDirect(*direct, pack, shaders, session);
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    printBuildSummary(options, buildOptions.shard, shaders, *build, sizes, seconds,
                      direct ? &direct->outcome() : nullptr, out);
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

int runExplain(const ExplainOptions& options, Session& session, std::ostream& out) {
    std::vector<frontend::LoadedShader> shaders;
    bool loaded = loadAll(options.input, session, shaders, options.compile.maxVariants);
    session.printNew(DiagnosticRule::Input);
    if (!loaded) return kExitFailure;
    auto shader = std::find_if(shaders.begin(), shaders.end(), [&](const auto& candidate) {
        return candidate.ast.name == options.shader;
    });
    if (shader == shaders.end()) {
        session.output.error("no shader named \"" + options.shader + "\" in the inputs");
        return kExitFailure;
    }
    int passPosition = findLoadedPass(*shader, options.pass);
    if (passPosition < 0) {
        session.output.error("shader \"" + options.shader + "\" has no pass '" + options.pass +
                             "' with a program");
        return kExitFailure;
    }
    // With a project, a variant that does not ship is explained, not compiled.
    std::string projectReason;
    const frontend::LoadedPass& planned = shader->passes[static_cast<size_t>(passPosition)];
    if (planned.plan && options.variant) {
        bool ships = false;
        projectReason = frontend::explainVariant(
            *planned.plan, planned.space->table().keyOf(splitKeywords(*options.variant)), ships);
        if (!ships) {
            out << (options.json ? nlohmann::ordered_json{{"project", projectReason}}.dump()
                                 : "Variant \"" + *options.variant + "\": " + projectReason)
                << "\n";
            return kExitOk;
        }
    }
    std::vector<frontend::LoadedShader> one;
    one.push_back(std::move(*shader));  // LoadedPass::pass stays valid: the AST moves whole
    driver::BuildOptions buildOptions = toBuildOptions(options.compile, options.input);
    buildOptions.keepPrunedSources = true;
    auto build = driver::buildPrograms(one, session.sourceMap, buildOptions, session.diagnostics);
    session.printNew(DiagnosticRule::Compile);
    if (!build) return kExitFailure;
    auto compiled = std::find_if(build->passes.begin(), build->passes.end(), [&](const auto& p) {
        return p.passIndex == static_cast<size_t>(passPosition);
    });
    if (compiled == build->passes.end()) {
        session.output.error("pass '" + options.pass + "' is not built for Vulkan");
        return kExitFailure;
    }
    const frontend::LoadedPass& pass = one.front().passes[static_cast<size_t>(passPosition)];
    ExplainRequest request{&one.front(), &pass, &*compiled, &*build, std::nullopt, std::nullopt};
    if (options.variant) {
        request.variant = explainedVariant(pass, *compiled, *options.variant, session);
        if (!request.variant) return kExitFailure;
    }
    if (options.diff) {
        auto a = explainedVariant(pass, *compiled, options.diff->first, session);
        auto b = explainedVariant(pass, *compiled, options.diff->second, session);
        if (!a || !b) return kExitFailure;
        request.diff = std::make_pair(*a, *b);
    }
    nlohmann::ordered_json report = explainJson(request, session.sourceMap);
    if (!projectReason.empty()) report["project"] = projectReason;
    if (options.json) {
        out << report.dump() << "\n";
    } else {
        if (!projectReason.empty()) out << "Project: " << projectReason << "\n";
        printExplainText(report, out);
    }
    return kExitOk;
}

// Runs a command that reads shaders, then writes the JSON or SARIF document of its diagnostics,
// whatever path it took.
template <typename T, typename Run>
int runShaderCommand(const T& options, std::ostream& err, Run run) {
    Session session(options.input.diagnosticsFormat, err);
    int exitCode = run(options, session);
    session.output.finish();
    return exitCode;
}

int runCommand(const CommandOptions& command, std::ostream& out, std::ostream& err) {
    auto withSession = [&out](auto run) {
        return [&out, run](const auto& options, Session& session) {
            return run(options, session, out);
        };
    };
    if (auto* o = std::get_if<VariantsOptions>(&command))
        return runShaderCommand(*o, err, withSession(runVariants));
    if (auto* o = std::get_if<LockOptions>(&command))
        return runShaderCommand(*o, err, withSession(runLock));
    if (auto* o = std::get_if<CheckOptions>(&command))
        return runShaderCommand(*o, err, withSession(runCheck));
    if (auto* o = std::get_if<BuildCommandOptions>(&command)) {
        return runShaderCommand(*o, err, [&](const BuildCommandOptions& options, Session& session) {
            return runBuild(options, session, out, err);
        });
    }
    if (auto* o = std::get_if<ExplainOptions>(&command))
        return runShaderCommand(*o, err, withSession(runExplain));
    if (auto* o = std::get_if<MergeOptions>(&command)) return runMerge(*o, out, err);
    if (auto* o = std::get_if<InfoOptions>(&command)) return runInfo(*o, out, err);
    if (auto* o = std::get_if<ExtractOptions>(&command)) return runExtract(*o, out, err);
    if (auto* o = std::get_if<LookupOptions>(&command)) return runLookup(*o, out, err);
    if (auto* o = std::get_if<RenderOptions>(&command)) return runRender(*o, out, err);
    if (auto* o = std::get_if<ValidateOptions>(&command)) return runValidate(*o, out, err);
    return runCache(std::get<CacheOptions>(command), out, err);
}

}  // namespace

int runCli(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
    // The hidden worker mode (driver::OptimizerPool spawns it), before any option parsing.
    if (argc == 2 && argv[1] == driver::kOptimizerWorkerCommand)
        return driver::runOptimizerWorker(STDIN_FILENO);
    ParsedCommandLine parsed = parseCommandLine(argc, argv, out, err);
    if (!parsed.command) return parsed.exitCode;
    return runCommand(*parsed.command, out, err);
}

}  // namespace varc::cli
