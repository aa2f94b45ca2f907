// SPDX-License-Identifier: Apache-2.0
// loadProject: packages, the asset walk, GUIDs, then materials, collections and settings.
#include "varc/project/Project.h"

#include <algorithm>
#include <map>

#include "AssetScanner.h"
#include "GraphicsSettingsReader.h"
#include "LoadContext.h"
#include "MaterialReader.h"
#include "PackageLocator.h"
#include "ShaderGuidIndex.h"
#include "VariantCollectionReader.h"

namespace varc::project {

namespace fs = std::filesystem;

namespace {

// The areas to walk and the include roots, from the layout and the packages found.
std::vector<AssetArea> assetAreas(Project& project, const LoadOptions& options) {
    auto overlaysOf = [&](const fs::path& folder) {
        std::vector<fs::path> overlays;
        fs::path relative = folder.lexically_relative(project.root);
        bool inside = !relative.empty() && *relative.begin() != "..";
        for (const fs::path& sourceRoot : options.shaderSourceRoots) {
            if (inside) overlays.push_back((sourceRoot / relative).lexically_normal());
        }
        return overlays;
    };
    std::vector<AssetArea> areas;
    IncludeRoots& roots = project.includeRoots;
    roots.projectRoots.push_back(project.root);
    for (const fs::path& sourceRoot : options.shaderSourceRoots)
        roots.projectRoots.push_back(sourceRoot);
    if (project.layout == ProjectLayout::AssetFolder) {
        areas.push_back({project.root, "", options.shaderSourceRoots});
        return areas;
    }
    areas.push_back({project.root / "Assets", "Assets", overlaysOf(project.root / "Assets")});
    for (const ProjectPackage& package : project.packages) {
        AssetArea area{package.folder, "Packages/" + package.name, overlaysOf(package.folder)};
        std::vector<fs::path>& folders = roots.packages[area.assetPrefix];
        folders.push_back(package.folder);
        folders.insert(folders.end(), area.overlayFolders.begin(), area.overlayFolders.end());
        areas.push_back(std::move(area));
    }
    return areas;
}

// Shaders with their GUIDs; a `.shader.meta` whose shader is nowhere still names an entry (with
// no file) so references to its GUID resolve to the path Unity would use.
void collectShaders(const AssetFiles& files, Project& project, ShaderGuidIndex& index,
                    LoadContext& context) {
    std::map<std::string, ProjectShader> byPath;
    for (const ScannedFile& shader : files.shaders)
        byPath[shader.assetPath] = {shader.assetPath, shader.file, ""};
    for (const ScannedFile& meta : files.shaderMetas) {
        std::string guid = readMetaGuid(meta.file, context);
        auto [entry, added] =
            byPath.try_emplace(meta.assetPath, ProjectShader{meta.assetPath, {}, ""});
        if (added) {
            context.warn(meta.file, "no " + fs::path(meta.assetPath).filename().string() +
                                        " beside this .meta (nor in a shader source root)");
        }
        if (guid.empty()) continue;
        entry->second.guid = guid;
        index.add(guid, meta.assetPath, meta.file, context);
    }
    for (auto& [path, shader] : byPath) project.shaders.push_back(std::move(shader));
}

void readAssets(const AssetFiles& files, const ShaderGuidIndex& index, Project& project,
                LoadContext& context) {
    std::map<std::string, std::string> collectionGuids;  // asset path -> GUID
    std::map<std::string, std::string> collectionPaths;  // GUID -> asset path
    for (const ScannedFile& meta : files.collectionMetas) {
        std::string guid = readMetaGuid(meta.file, context);
        if (guid.empty()) continue;
        collectionGuids[meta.assetPath] = guid;
        collectionPaths.emplace(guid, meta.assetPath);
    }
    for (const ScannedFile& file : files.materials) {
        try {
            for (Material& material : readMaterials(file.file, file.assetPath, index, context)) {
                project.materials.push_back(std::move(material));
            }
        } catch (const std::exception& error) {  // yaml-cpp throws from accessors on odd input
            context.warn(file.file, std::string("not read: ") + error.what());
        }
    }
    for (const ScannedFile& file : files.collections) {
        try {
            auto guid = collectionGuids.find(file.assetPath);
            auto collection = readVariantCollection(
                file.file, file.assetPath, guid == collectionGuids.end() ? "" : guid->second, index,
                context);
            if (collection) project.variantCollections.push_back(std::move(*collection));
        } catch (const std::exception& error) {
            context.warn(file.file, std::string("not read: ") + error.what());
        }
    }
    fs::path settings = project.root / "ProjectSettings" / "GraphicsSettings.asset";
    std::error_code exists;
    if (project.layout == ProjectLayout::UnityProject && fs::exists(settings, exists)) {
        try {
            project.graphicsSettings =
                readGraphicsSettings(settings, index, collectionPaths, context);
        } catch (const std::exception& error) {
            context.warn(settings, std::string("not read: ") + error.what());
        }
    }
}

}  // namespace

Project loadProject(const fs::path& root, DiagnosticSink& sink, const LoadOptions& options) {
    Project project;
    project.root = root.lexically_normal();
    LoadContext context(project, sink, options);
    std::error_code error;
    if (!fs::is_directory(project.root, error)) {
        sink.error({context.fileId(project.root), 0, 0}, "not a folder: cannot read the project");
        return project;
    }
    project.layout = fs::is_directory(project.root / "Assets", error) ? ProjectLayout::UnityProject
                                                                      : ProjectLayout::AssetFolder;
    if (project.layout == ProjectLayout::UnityProject) {
        PackageSearch search = locatePackages(project.root, options.includeUnityIgnored, context);
        project.packages = std::move(search.packages);
        project.packagesNotOnDisk = std::move(search.notOnDisk);
    }
    try {  // the library boundary: readers catch per file, this catches what slips past them
        std::vector<AssetArea> areas = assetAreas(project, options);
        AssetFiles files = scanAssets(areas, options.includeUnityIgnored, context);
        ShaderGuidIndex index;
        collectShaders(files, project, index, context);
        readAssets(files, index, project, context);
    } catch (const std::exception& failure) {
        context.warn(project.root, std::string("project not read completely: ") + failure.what());
    }
    return project;
}

const ProjectShader* Project::findShaderByGuid(std::string_view guid) const {
    if (guid.empty()) return nullptr;
    for (const ProjectShader& shader : shaders) {
        if (shader.guid == guid) return &shader;
    }
    return nullptr;
}

std::string Project::describe(SourceLocation location) const {
    if (location.file == kNoFile || location.file >= files.size()) return "<unknown>";
    std::string text = files[location.file].string();
    if (location.line == 0) return text;
    text += ":" + std::to_string(location.line);
    if (location.column != 0) text += ":" + std::to_string(location.column);
    return text;
}

}  // namespace varc::project
