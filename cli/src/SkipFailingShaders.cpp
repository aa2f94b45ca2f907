// SPDX-License-Identifier: Apache-2.0
// `varc build --skip-failing-shaders`: finding the shaders that fail alone and building the rest.
#include "varc/cli/SkipFailingShaders.h"

#include <stdlib.h>

#include <filesystem>
#include <set>
#include <system_error>

#include "varc/cache/CacheSpec.h"

namespace varc::cli {

namespace {

// What tells two reports of one problem apart from two problems (notes, such as the number of
// variants an error affects, differ between a shader's build alone and the build of all).
std::string problemKey(const Diagnostic& diagnostic) {
    const SourceLocation& at = diagnostic.location;
    return std::to_string(static_cast<int>(diagnostic.severity)) + ":" + std::to_string(at.file) +
           ":" + std::to_string(at.line) + ":" + std::to_string(at.column) + ":" +
           diagnostic.message;
}

}  // namespace

std::optional<BuiltPack> buildWithoutFailingShaders(std::vector<frontend::LoadedShader>& shaders,
                                                    const PackBuildStep& buildPack,
                                                    std::vector<std::string>& leftOut,
                                                    DiagnosticList& reported) {
    std::set<std::string> known;
    for (const Diagnostic& diagnostic : reported.diagnostics())
        known.insert(problemKey(diagnostic));
    std::vector<frontend::LoadedShader> kept;
    for (frontend::LoadedShader& shader : shaders) {
        DiagnosticList alone;
        std::vector<frontend::LoadedShader> one;
        one.push_back(std::move(shader));  // LoadedPass::pass stays valid: the AST moves whole
        if (buildPack(one, alone)) {
            kept.push_back(std::move(one.front()));
            continue;
        }
        leftOut.push_back(one.front().path);
        // The build of all stops before later checks (stage interfaces, assembly) once a program
        // fails: the errors only this build found are reported now.
        for (const Diagnostic& diagnostic : alone.diagnostics()) {
            if (known.insert(problemKey(diagnostic)).second) reported.report(diagnostic);
        }
    }
    shaders = std::move(kept);
    if (shaders.empty()) return std::nullopt;
    DiagnosticList diagnostics;
    std::optional<BuiltPack> built = buildPack(shaders, diagnostics);
    // Shaders that build alone but not together would be a dependency buildPack must not have.
    if (!built) {
        for (const Diagnostic& diagnostic : diagnostics.diagnostics()) reported.report(diagnostic);
    }
    return built;
}

ScratchProgramCache::~ScratchProgramCache() {
    if (mDirectory.empty()) return;
    std::error_code error;
    std::filesystem::remove_all(mDirectory, error);  // a folder this object made, and its entries
}

std::shared_ptr<cache::CacheChain> ScratchProgramCache::levelsFor(
    const driver::BuildOptions& options) {
    if (options.cache) return options.cache;
    if (mDirectory.empty()) {
        std::error_code error;
        std::filesystem::path base = std::filesystem::temp_directory_path(error);
        if (error) return nullptr;
        std::string pattern = (base / "varc-skip-XXXXXX").string();
        if (!::mkdtemp(pattern.data())) return nullptr;
        mDirectory = pattern;
    }
    return std::make_shared<cache::CacheChain>(
        cache::CacheChain::open({cache::directoryCacheSpec(mDirectory)}));
}

}  // namespace varc::cli
