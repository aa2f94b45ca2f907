// SPDX-License-Identifier: Apache-2.0
// `varc build`: load, compile, assemble and write one pack (direct mode, shards, and
// --skip-failing-shaders included), then the summary.
#include "BuildCommand.h"

#include <unistd.h>

#include <chrono>
#include <functional>
#include <iomanip>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <sstream>

#include "varc/cli/BuildReport.h"
#include "varc/cli/DirectMode.h"
#include "varc/cli/DriverOptions.h"
#include "varc/cli/SkipFailingShaders.h"
#include "varc/core/AtomicFile.h"
#include "varc/driver/CompileDriver.h"
#include "varc/driver/Depfile.h"
#include "varc/driver/PackAssembler.h"
#include "varc/pack/PartialPack.h"
#include "varc/packwriter/PackWriter.h"

namespace varc::cli {

namespace {

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
    return contents;
}

// Compiles and assembles |shaders|, reporting to the session; nullopt after errors.
std::optional<BuiltPack> buildPack(const BuildCommandOptions& options,
                                   const driver::BuildOptions& buildOptions,
                                   const std::vector<frontend::LoadedShader>& shaders,
                                   Session& session) {
    auto build =
        driver::buildPrograms(shaders, session.sourceMap, buildOptions, session.diagnostics);
    session.printNew(DiagnosticRule::Compile);
    if (!build) return std::nullopt;
    auto contents = assembleBuiltPack(options, buildOptions, shaders, *build, session);
    if (!contents) return std::nullopt;
    return BuiltPack{std::move(*build), std::move(*contents)};
}

// --skip-failing-shaders after a failed build: the pack of the shaders that build alone (the
// rebuilds share the first build's program cache, so nothing compiles twice).
std::optional<BuiltPack> buildSkippingFailures(const BuildCommandOptions& options,
                                               driver::BuildOptions buildOptions,
                                               std::vector<frontend::LoadedShader>& shaders,
                                               std::vector<std::string>& leftOut,
                                               Session& session) {
    buildOptions.progress = {};
    std::string fingerprint = "optimization=" + optimizationFlag(options.compile.optimization) +
                              (options.compile.debugNames ? " -g" : "");
    PackBuildStep step = [&](const std::vector<frontend::LoadedShader>& some,
                             DiagnosticSink& sink) -> std::optional<BuiltPack> {
        auto build = driver::buildPrograms(some, session.sourceMap, buildOptions, sink);
        if (!build || !driver::checkStageInterfaces(some, *build, sink)) return std::nullopt;
        auto contents = driver::assemblePack(some, *build, session.sourceMap,
                                             buildOptions.sourcePaths, fingerprint, sink);
        if (!contents) return std::nullopt;
        return BuiltPack{std::move(*build), std::move(*contents)};
    };
    auto built = buildWithoutFailingShaders(shaders, step, leftOut, session.diagnostics);
    session.printNew(DiagnosticRule::Compile);
    return built;
}

// The warning that names the shaders --skip-failing-shaders left out of the pack.
void reportLeftOut(const std::vector<std::string>& leftOut, Session& session) {
    std::string files;
    for (const std::string& file : leftOut) files += (files.empty() ? "" : ", ") + file;
    session.diagnostics.warning({}, std::to_string(leftOut.size()) + " shader" +
                                        (leftOut.size() == 1 ? "" : "s") +
                                        " left out of the pack (--skip-failing-shaders; errors "
                                        "above): " +
                                        files);
    session.printNew(DiagnosticRule::Compile);
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
        if (options.compile.sampleVariants > 0)
            report["sample_variants"] = options.compile.sampleVariants;
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
    if (options.compile.sampleVariants > 0) {
        out << "Sampled: at most " << options.compile.sampleVariants
            << " variants of each pass were built (--sample-variants); this pack is a check, "
               "not one to ship\n";
    }
    if (direct) out << directSummaryLine(*direct) << "\n";
    out << "wrote " << options.outputPath << "\n";
}

}  // namespace

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
    std::vector<std::string> leftOut;  // --skip-failing-shaders: the files of failing shaders
    bool loaded = loadAll(options.input, session, shaders, options.compile.maxVariants,
                          options.skipFailingShaders ? &leftOut : nullptr);
    session.printNew(DiagnosticRule::Input);  // errors, or warnings
    if (!loaded) return kExitFailure;
    if (!session.output.isDocument()) buildOptions.progress = progressPrinter(err);
    // --skip-failing-shaders reports every failure, and its rebuilds share a program cache
    // (the user's, else a scratch one whose statistics are not reported).
    ScratchProgramCache scratch;
    const bool scratchCache = options.skipFailingShaders && !buildOptions.cache;
    if (options.skipFailingShaders) {
        buildOptions.keepGoing = true;
        buildOptions.cache = scratch.levelsFor(buildOptions);
    }
    std::optional<BuiltPack> built;
    if (!shaders.empty() || leftOut.empty())
        built = buildPack(options, buildOptions, shaders, session);
    if (!built && options.skipFailingShaders)
        built = buildSkippingFailures(options, buildOptions, shaders, leftOut, session);
    if (!built) {
        session.output.summary("varc build: failed; " + options.outputPath + " was not written");
        return kExitFailure;
    }
    if (scratchCache) built->build.cacheLevels.clear();
    if (!leftOut.empty()) reportLeftOut(leftOut, session);
    const driver::BuildOutput* build = &built->build;
    PackSizes sizes = measureSpirv(*build);
    std::string pack;
    if (!writeBuildFiles(options, built->contents, shaders, sizes, session, pack)) {
        return kExitFailure;
    }
    if (direct) recordDirect(*direct, pack, shaders, session);
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    printBuildSummary(options, buildOptions.shard, shaders, *build, sizes, seconds,
                      direct ? &direct->outcome() : nullptr, out);
    return kExitOk;
}

}  // namespace varc::cli
