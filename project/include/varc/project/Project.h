// SPDX-License-Identifier: Apache-2.0
// A Unity project folder read into plain data: shaders, materials, collections, settings.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "varc/core/Diagnostic.h"
#include "varc/project/AssetReference.h"
#include "varc/project/GraphicsSettings.h"
#include "varc/project/IncludeRoots.h"
#include "varc/project/Material.h"
#include "varc/project/ShaderVariantCollection.h"

namespace varc::project {

// A `.shader` of the project (or one its `.meta` announces).
struct ProjectShader {
    std::string path;            // asset path: "Assets/..." or "Packages/<package name>/..."
    std::filesystem::path file;  // on disk (project or shader source root); empty if not found
    std::string guid;            // from `<file>.meta`; empty without a .meta
};

enum class PackageSource { Embedded, Local, Cache };

// A package whose assets the project reads.
struct ProjectPackage {
    std::string name;     // package.json `name`; the folder name when it has none
    std::string version;  // from manifest.json; empty for embedded packages
    PackageSource source = PackageSource::Embedded;
    std::filesystem::path folder;  // on disk
};

enum class ProjectLayout {
    UnityProject,  // the root has `Assets/`: Assets/ and packages are read
    AssetFolder,   // no `Assets/` (a package or shader collection repository): every file counts
};

struct LoadOptions {
    // Folders whose files at the same relative paths as the project's supply `.shader` files
    // (and includes) the project folder itself lacks. Tests and the CLI read the compatibility
    // corpus this way: `compat/projects/<repo>` holds materials and `.meta` files, the shaders
    // are in `compat/<repo>` and `compat/surface/<repo>`. The project's own files win.
    std::vector<std::filesystem::path> shaderSourceRoots;
    // Unity skips folders and files named `.*`, `*~` (e.g. a package's `Samples~`), `cvs` and
    // `*.tmp`; true reads them too.
    bool includeUnityIgnored = false;
    // Gives each file a diagnostic names its FileId (e.g. registering it in the caller's
    // SourceMap). Unset: the project numbers them itself, see Project::files.
    std::function<FileId(const std::filesystem::path&)> fileIdFor;
};

struct Project {
    std::filesystem::path root;
    ProjectLayout layout = ProjectLayout::UnityProject;
    std::vector<ProjectShader> shaders;          // sorted by path
    std::vector<ProjectPackage> packages;        // sorted by name
    std::vector<std::string> packagesNotOnDisk;  // manifest entries with no folder found, sorted
    IncludeRoots includeRoots;
    std::vector<Material> materials;  // sorted by path (then document order)
    std::vector<ShaderVariantCollection> variantCollections;  // sorted by path
    std::optional<GraphicsSettings> graphicsSettings;         // nullopt: no readable text file
    // Without LoadOptions::fileIdFor: the files diagnostics name, FileId = index.
    std::vector<std::filesystem::path> files;

    // The shader whose `.meta` has |guid|, or nullptr.
    const ProjectShader* findShaderByGuid(std::string_view guid) const;
    // "path:line:col", "path:line" or "path" for a location in |files|; "<unknown>" otherwise.
    std::string describe(SourceLocation location) const;
};

// Reads the Unity project at |root|. Never throws and never stops at a bad file: binary
// (non-text) assets, malformed YAML, missing fields and GUIDs no `.meta` defines each give a
// warning naming the file (with line and column where known), and the item is taken as Unity
// takes it (a binary material is skipped, an unknown GUID is a material whose shader is
// unknown). Errors only when |root| is not a readable folder.
Project loadProject(const std::filesystem::path& root, DiagnosticSink& sink,
                    const LoadOptions& options = {});

}  // namespace varc::project
