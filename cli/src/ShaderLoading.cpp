// SPDX-License-Identifier: Apache-2.0
// Loading the inputs of a command that reads shaders: PATHs or a project, then the plan.
#include <filesystem>
#include <set>
#include <string>
#include <utility>

#include "Session.h"
#include "UsageLog.h"
#include "varc/cli/ShaderInputs.h"
#include "varc/frontend/ShaderCatalog.h"

namespace varc::cli {

namespace {

includes::IncludeOptions includeOptions(const ShaderInputOptions& input) {
    includes::IncludeOptions result;
    result.includeDirs = input.includeDirs;
    result.builtinDir = input.builtinIncludeDir;
    result.projectRoot = input.projectRoot;
    return result;
}

// With PATH arguments beside --project, only the build's shaders under them.
std::vector<std::string> restrictToPaths(const std::vector<std::string>& files,
                                         const std::vector<std::string>& paths,
                                         DiagnosticSink& sink) {
    namespace fs = std::filesystem;
    if (paths.empty()) return files;
    std::set<std::string> wanted;
    for (const std::string& path : findShaderFiles(paths, sink)) {
        wanted.insert(fs::weakly_canonical(path).generic_string());
    }
    std::vector<std::string> kept;
    for (const std::string& file : files) {
        if (wanted.count(fs::weakly_canonical(file).generic_string())) kept.push_back(file);
    }
    return kept;
}

}  // namespace

bool loadAll(const ShaderInputOptions& input, Session& session,
             std::vector<frontend::LoadedShader>& shaders, uint64_t maxVariants,
             std::vector<std::string>* failedFiles) {
    includes::IncludeOptions include = includeOptions(input);
    std::vector<std::string> files, searchFiles;
    DiagnosticList searchErrors;  // an unreadable include folder is reported by the includes
    if (!input.projectDir.empty()) {
        session.project =
            readProjectInputs(input, session.fileSystem, session.sourceMap, session.diagnostics);
        if (!session.project) return false;
        files = restrictToPaths(session.project->shaderFiles, input.inputs, session.diagnostics);
        include.virtualRoots = session.project->virtualRoots;
        searchFiles = session.project->allShaderFiles;
    } else {
        files = findShaderFiles(input.inputs, session.diagnostics);
    }
    for (std::string& file : findShaderFiles(input.includeDirs, searchErrors))
        searchFiles.push_back(std::move(file));
    // UsePass and Fallback find other shaders among the inputs, then in the project and under
    // the include folders.
    frontend::ShaderCatalog catalog(session.fileSystem, session.sourceMap, files, searchFiles,
                                    include.builtinDir);
    size_t shaderErrors = 0;  // reported while loading a shader that failedFiles then lists
    for (const std::string& file : files) {
        const size_t errorsBefore = session.diagnostics.errorCount();
        auto shader = frontend::loadShader(file, session.fileSystem, session.sourceMap, include,
                                           session.diagnostics, &catalog);
        const size_t errors = session.diagnostics.errorCount() - errorsBefore;
        if (shader && errors == 0) {
            shaders.push_back(std::move(*shader));
        } else if (failedFiles) {
            failedFiles->push_back(file);
            shaderErrors += errors;
        }
    }
    std::vector<variants::StripRule> rules;
    if (!input.stripRulesPath.empty() &&
        !readUserStripRules(input.stripRulesPath, session.sourceMap, session.diagnostics, rules)) {
        return false;
    }
    // A usage log asks like a variant collection: without a project, the shaders it names
    // get the variants it recorded (every multi_compile state with the shader_feature
    // combinations it used), the others their all-off combination.
    for (const std::string& path : input.usageLogs) {
        auto entries = readUsageLog(path, session.sourceMap, session.diagnostics);
        if (!entries) return false;
        if (!session.project) session.project.emplace();
        addUsageDemands(*entries, shaders, *session.project, session.diagnostics);
    }
    if (session.project || !input.stripRulesPath.empty()) {
        planShaders(session.project ? &*session.project : nullptr, rules, maxVariants, shaders,
                    session.diagnostics);
    }
    return session.diagnostics.errorCount() == shaderErrors;
}

}  // namespace varc::cli
