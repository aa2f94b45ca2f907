// SPDX-License-Identifier: Apache-2.0
// The `varc` command-line tool as a library: option parsing, then one command.
#include "varc/cli/Cli.h"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>
#include <ostream>

#include "BuildCommand.h"
#include "Session.h"
#include "varc/cli/CacheCommands.h"
#include "varc/cli/DiagnosticOutput.h"
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
#include "varc/driver/OptimizerWorker.h"
#include "varc/frontend/ShaderLoader.h"
#include "varc/frontend/VariantLimit.h"

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
