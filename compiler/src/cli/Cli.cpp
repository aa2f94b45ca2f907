// SPDX-License-Identifier: Apache-2.0
// The `varc` command-line tool as a library: option parsing, then one command.
#include "varc/compiler/cli/Cli.h"

#include <filesystem>
#include <ostream>

#include "varc/compiler/ShaderLoader.h"
#include "varc/compiler/cli/DiagnosticPrinter.h"
#include "varc/compiler/cli/LockCheck.h"
#include "varc/compiler/cli/LockFile.h"
#include "varc/compiler/cli/Options.h"
#include "varc/compiler/cli/ShaderInputs.h"
#include "varc/compiler/cli/VariantReport.h"
#include "varc/core/AtomicFile.h"

namespace varc::cli {

namespace {

// State shared by the commands: the files read and the diagnostics reported so far.
struct Session {
    includes::DiskFileSystem fileSystem;
    includes::SourceMap sourceMap;
    DiagnosticList diagnostics;
};

includes::IncludeOptions includeOptions(const Options& options) {
    includes::IncludeOptions result;
    result.includeDirs = options.includeDirs;
    result.builtinDir = options.builtinIncludeDir;
#ifdef VARC_DEFAULT_BUILTIN_INCLUDE_DIR
    if (result.builtinDir.empty()) result.builtinDir = VARC_DEFAULT_BUILTIN_INCLUDE_DIR;
#endif
    return result;
}

// Loads every input shader; false when any failed (diagnostics are in |session|).
bool loadAll(const Options& options, Session& session,
             std::vector<compiler::LoadedShader>& shaders) {
    std::vector<std::string> files = findShaderFiles(options.inputs, session.diagnostics);
    includes::IncludeOptions include = includeOptions(options);
    for (const std::string& file : files) {
        auto shader = compiler::loadShader(file, session.fileSystem, session.sourceMap, include,
                                           session.diagnostics);
        if (shader) shaders.push_back(std::move(*shader));
    }
    return !session.diagnostics.hasErrors();
}

int runVariants(const Options& options, Session& session, std::ostream& out, std::ostream& err) {
    std::vector<compiler::LoadedShader> shaders;
    bool ok = loadAll(options, session, shaders);
    printDiagnostics(session.diagnostics.diagnostics(), session.sourceMap, err);
    if (!ok) return kExitFailure;
    if (options.json) {
        out << variantsJson(shaders, options.list).dump() << "\n";
    } else {
        printVariantsText(shaders, session.sourceMap, options.list, out);
    }
    return kExitOk;
}

int runLock(const Options& options, Session& session, std::ostream& out, std::ostream& err) {
    std::vector<compiler::LoadedShader> shaders;
    bool ok = loadAll(options, session, shaders);
    printDiagnostics(session.diagnostics.diagnostics(), session.sourceMap, err);
    if (!ok) return kExitFailure;
    std::string lockDir = std::filesystem::path(options.lockPath).parent_path().string();
    LockFile lock = makeLock(shaders, lockDir);
    Status written = writeFileAtomically(options.lockPath, serializeLock(lock));
    if (!written) {
        err << "varc: error: " << written.error().detail << "\n";
        return kExitFailure;
    }
    out << "wrote " << options.lockPath << ": " << lock.shaders.size() << " shaders\n";
    return kExitOk;
}

std::optional<LockFile> readLock(const std::string& path, Session& session, std::ostream& err) {
    auto text = session.fileSystem.read(path);
    if (!text) {
        err << "varc: error: cannot read lock file '" << path << "'\n";
        return std::nullopt;
    }
    Result<LockFile> lock = parseLock(*text, path);
    if (!lock) {
        err << "varc: error: " << lock.error().detail << "\n";
        return std::nullopt;
    }
    return std::move(lock).value();
}

int runCheck(const Options& options, Session& session, std::ostream& out, std::ostream& err) {
    std::optional<LockFile> lock = readLock(options.lockPath, session, err);
    if (!lock) return kExitUsage;
    std::vector<compiler::LoadedShader> shaders;
    if (!loadAll(options, session, shaders)) {
        printDiagnostics(session.diagnostics.diagnostics(), session.sourceMap, err);
        return kExitUsage;
    }
    DiagnosticList findings;
    bool passed = checkAgainstLock(*lock, shaders, {options.maxGrowth, options.budget}, findings);
    printDiagnostics(findings.diagnostics(), session.sourceMap, err);
    if (!passed) {
        err << "varc check: variant counts differ from " << options.lockPath
            << "; if the change is intended, run `varc lock -o " << options.lockPath << "`\n";
        return kExitFailure;
    }
    out << "varc check: " << shaders.size() << " shaders match " << options.lockPath << "\n";
    return kExitOk;
}

}  // namespace

int runCli(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
    Options options;
    if (auto exitCode = parseOptions(argc, argv, options, out, err)) return *exitCode;
    Session session;
    switch (options.command) {
        case Command::Variants: return runVariants(options, session, out, err);
        case Command::Lock: return runLock(options, session, out, err);
        case Command::Check: return runCheck(options, session, out, err);
        case Command::None: break;
    }
    err << "varc: error: no command given\n";
    return kExitUsage;
}

}  // namespace varc::cli
