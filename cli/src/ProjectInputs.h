// SPDX-License-Identifier: Apache-2.0
// `--project DIR`: which shaders a Unity project builds and what its materials, variant
// collections and Graphics Settings ask of each (docs/PROJECTS.md).
#pragma once

#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "varc/cli/Options.h"
#include "varc/core/Diagnostic.h"
#include "varc/frontend/ShaderLoader.h"
#include "varc/frontend/VariantPlan.h"
#include "varc/includes/FileSystem.h"
#include "varc/includes/IncludeResolver.h"
#include "varc/includes/SourceMap.h"

namespace varc::cli {

// What the project contributes to a command, ready for loading and planning.
struct ProjectInputs {
    std::string root;                       // the --project folder
    std::vector<std::string> shaderFiles;   // the shaders in the build, on disk, sorted
    std::vector<std::string> allShaderFiles;  // every project shader on disk (UsePass, Fallback)
    std::map<std::string, frontend::ShaderDemand> demands;  // by shaderFiles entry
    std::map<std::string, FileId> requestFiles;  // material or collection asset path -> file
    std::vector<includes::IncludeOptions::VirtualRoot> virtualRoots;  // Assets/, Packages/<n>/
    size_t projectShaders = 0;              // .shader files the project has
    size_t materials = 0;                   // readable materials
    size_t collections = 0;                 // ShaderVariantCollections
    std::string stripping;                  // "lightmap automatic, fog custom, instancing ..."
};

// Reads the project |input| names (--project, --project-shaders, --builtin-shaders) and decides
// its build: the shaders a material or collection uses, and those Graphics Settings always
// include. Files it reads are registered in |sourceMap| so diagnostics name them. Warnings for
// what cannot be resolved (a built-in shader with no source given, a shader outside the folder);
// nullopt only when the project folder cannot be read.
std::optional<ProjectInputs> readProjectInputs(const ShaderInputOptions& input,
                                               const includes::FileSystem& fileSystem,
                                               includes::SourceMap& sourceMap,
                                               DiagnosticSink& sink);

// "Project game/: 12 shaders, 3 in the build; 99 materials, 0 variant collections; stripping:
// lightmap automatic (every mode kept), fog custom, instancing strip unused".
std::string projectSummary(const ProjectInputs& inputs);
// {"root","shaders","in_build","materials","collections","stripping"}.
nlohmann::ordered_json projectJson(const ProjectInputs& inputs);

// Reads the user's strip rules from |path| into |rules|; false after reporting errors.
bool readUserStripRules(const std::string& path, includes::SourceMap& sourceMap,
                        DiagnosticSink& sink, std::vector<variants::StripRule>& rules);

// Sets the plan of every pass of |shaders| from the project's demand (|inputs|; without a project
// every declared variant is demanded) and the user's strip |rules|, enumerating at most |limit|
// variants per pass. Warns once per material about keywords no pass of its shader declares
// (Unity ignores them), and about each rule that removed no variant.
void planShaders(const ProjectInputs* inputs, const std::vector<variants::StripRule>& rules,
                 uint64_t limit, std::vector<frontend::LoadedShader>& shaders,
                 DiagnosticSink& sink);

}  // namespace varc::cli
