// SPDX-License-Identifier: Apache-2.0
// `--project DIR`: the shaders a Unity project builds and what it asks of each.
#include "ProjectInputs.h"

#include <filesystem>
#include <set>
#include <utility>

#include "varc/cli/SettingsStripping.h"
#include "varc/cli/ShaderInputs.h"
#include "varc/core/FileRead.h"
#include "varc/frontend/ShaderCatalog.h"
#include "varc/project/BuiltinShaders.h"
#include "varc/project/Project.h"
#include "varc/project/StripRuleFile.h"

namespace varc::cli {

namespace fs = std::filesystem;

namespace {

// Finds the source of the shader a reference names: a project shader by its asset path, a
// built-in one by its Unity name among the project's shaders and --builtin-shaders folders.
// Unresolved references are collected and reported once each by reportUnresolved().
class ShaderResolver {
public:
    ShaderResolver(const project::Project& project, const ShaderInputOptions& input,
                   const includes::FileSystem& fileSystem, includes::SourceMap& sourceMap)
        : mInput(input), mFileSystem(fileSystem), mSourceMap(sourceMap) {
        for (const project::ProjectShader& shader : project.shaders) {
            if (!shader.file.empty()) mByAssetPath[shader.path] = shader.file.generic_string();
        }
    }

    // The file of |reference|, used by |user| (a material, collection or the settings file).
    std::optional<std::string> resolve(const project::ShaderReference& reference,
                                       SourceLocation user) {
        using Kind = project::ShaderReferenceKind;
        if (reference.kind == Kind::Project) {
            auto it = mByAssetPath.find(reference.shaderPath);
            if (it != mByAssetPath.end()) return it->second;
            note(user, "shader '" + reference.shaderPath + "'",
                 "is not in the project folder (--project-shaders names a folder with the "
                 "project's sources)");
        } else if (reference.kind == Kind::Builtin) {
            return resolveBuiltin(reference, user);
        }
        return std::nullopt;  // unknown GUIDs and missing references: the loader warned
    }

    // One note for all of them: Graphics Settings always include Unity's own hidden shaders,
    // whose sources a project rarely has; the build leaving them out is expected.
    void reportUnresolvedAsOneNote(DiagnosticSink& sink, const std::string& what) const {
        if (mUnresolved.empty()) return;
        std::string list;
        for (const auto& [shader, entry] : mUnresolved) list += (list.empty() ? "" : ", ") + shader;
        sink.report({Severity::Note, mUnresolved.begin()->second.users.front(),
                     std::to_string(mUnresolved.size()) + " " + what +
                         " are left out of the build (no source here; --builtin-shaders DIR "
                         "names Unity's built-in shaders): " + list,
                     {}});
    }

    // One warning per unresolved shader, at its first user, counting the others.
    void reportUnresolved(DiagnosticSink& sink) const {
        for (const auto& [shader, entry] : mUnresolved) {
            size_t more = entry.users.size() - 1;
            std::string others =
                more > 0 ? " (and " + std::to_string(more) + " more uses)" : std::string();
            sink.report({Severity::Warning, entry.users.front(),
                         shader + " " + entry.why + others + "; the build leaves it out", {}});
        }
    }

private:
    std::optional<std::string> resolveBuiltin(const project::ShaderReference& reference,
                                              SourceLocation user) {
        const project::AssetReference& asset = reference.asset;
        std::optional<std::string_view> name =
            project::builtinShaderName(asset.guid, asset.fileId);
        if (!name) {
            note(user, "built-in shader fileID " + std::to_string(asset.fileId),
                 "is not one varc can name");
            return std::nullopt;
        }
        std::vector<std::string_view> names = {*name};
        for (std::string_view alias : project::builtinShaderAliases(asset.guid, asset.fileId))
            names.push_back(alias);
        for (std::string_view candidate : names) {
            if (const shaderlab::ShaderFile* found = catalog().find(candidate)) {
                return mSourceMap.path(found->location.file);
            }
        }
        note(user, "built-in shader \"" + std::string(*name) + "\" (fileID " +
                       std::to_string(asset.fileId) + ")",
             "has no source here (--builtin-shaders DIR names Unity's built-in shaders)");
        return std::nullopt;
    }

    frontend::ShaderCatalog& catalog() {
        if (!mCatalog) {
            DiagnosticList ignored;  // unreadable folders: the shaders are simply not found
            std::vector<std::string> files = findShaderFiles(mInput.builtinShaderDirs, ignored);
            for (const auto& [path, file] : mByAssetPath) files.push_back(file);
            // Not varc's own fallback shaders: those stand in for borrowed passes only (a
            // shadow caster), never for the shader a material draws with.
            mCatalog.emplace(mFileSystem, mSourceMap, std::vector<std::string>{}, files,
                             std::string());
        }
        return *mCatalog;
    }

    // |what| is the shader ("built-in shader \"UI/Default\" (fileID 10770)"), |why| the reason.
    void note(SourceLocation user, std::string what, std::string why) {
        Unresolved& entry = mUnresolved[std::move(what)];
        entry.why = std::move(why);
        entry.users.push_back(user);
    }

    const ShaderInputOptions& mInput;
    const includes::FileSystem& mFileSystem;
    includes::SourceMap& mSourceMap;
    std::map<std::string, std::string> mByAssetPath;
    std::optional<frontend::ShaderCatalog> mCatalog;
    struct Unresolved {
        std::string why;
        std::vector<SourceLocation> users;
    };
    std::map<std::string, Unresolved> mUnresolved;  // by what
};

FileId registerFile(includes::SourceMap& sourceMap, const fs::path& path) {
    std::string name = path.generic_string();
    if (std::optional<FileId> known = sourceMap.find(name)) return *known;
    Result<std::string> text = readFile(name, size_t{1} << 26);
    return sourceMap.addFile(name, text ? std::move(*text) : std::string());
}

std::string strippingSummary(const std::optional<project::GraphicsSettings>& settings) {
    auto mode = [](std::optional<int> value) {
        return value.value_or(0) == 1 ? "custom" : "automatic (every mode kept)";
    };
    static const char* const kInstancing[] = {"strip unused", "strip all", "keep all"};
    int instancing = settings ? settings->instancingStripping.value_or(0) : 0;
    return std::string("lightmap ") + mode(settings ? settings->lightmapStripping : std::nullopt) +
           ", fog " + mode(settings ? settings->fogStripping : std::nullopt) + ", instancing " +
           (instancing >= 0 && instancing <= 2 ? kInstancing[instancing] : "unknown");
}

std::vector<includes::IncludeOptions::VirtualRoot> virtualRootsOf(const project::Project& project) {
    std::vector<includes::IncludeOptions::VirtualRoot> roots;
    for (const fs::path& root : project.includeRoots.projectRoots) {
        roots.push_back({"Assets", (root / "Assets").generic_string()});
    }
    for (const auto& [prefix, folders] : project.includeRoots.packages) {
        for (const fs::path& folder : folders) roots.push_back({prefix, folder.generic_string()});
    }
    return roots;
}

// Materials and collections: the keyword requests of every shader they use.
void addRequests(const project::Project& project, ShaderResolver& resolver,
                 includes::SourceMap& sourceMap, ProjectInputs& inputs,
                 std::set<std::string>& instanced) {
    for (const project::Material& material : project.materials) {
        SourceLocation where{registerFile(sourceMap, material.file), 0, 0};
        inputs.requestFiles[material.path] = where.file;
        std::optional<std::string> file = resolver.resolve(material.shader, where);
        if (!file) continue;
        // Keywords saved as invalid count too: the shader may declare them again since.
        inputs.demands[*file].requests.push_back({variants::RequestKind::Material, material.path,
                                                  material.keywordsIncludingInvalid()});
        if (material.enableInstancingVariants) instanced.insert(*file);
    }
    for (const project::ShaderVariantCollection& collection : project.variantCollections) {
        SourceLocation where{registerFile(sourceMap, collection.file), 0, 0};
        inputs.requestFiles[collection.path] = where.file;
        for (const project::CollectedShader& shader : collection.shaders) {
            std::optional<std::string> file = resolver.resolve(shader.shader, where);
            if (!file) continue;
            frontend::ShaderDemand& demand = inputs.demands[*file];
            for (const project::CollectedVariant& variant : shader.variants) {
                demand.collectionRequests.push_back(
                    {variant.passType,
                     {variants::RequestKind::CollectionVariant, collection.path, variant.keywords}});
            }
        }
    }
}

}  // namespace

std::optional<ProjectInputs> readProjectInputs(const ShaderInputOptions& input,
                                               const includes::FileSystem& fileSystem,
                                               includes::SourceMap& sourceMap,
                                               DiagnosticSink& sink) {
    project::LoadOptions options;
    for (const std::string& folder : input.projectShaders) options.shaderSourceRoots.push_back(folder);
    options.fileIdFor = [&sourceMap](const fs::path& path) { return registerFile(sourceMap, path); };
    DiagnosticList loading;
    project::Project project = project::loadProject(input.projectDir, loading, options);
    for (const Diagnostic& diagnostic : loading.diagnostics()) sink.report(diagnostic);
    if (loading.hasErrors()) return std::nullopt;

    ProjectInputs inputs;
    inputs.root = input.projectDir;
    inputs.projectShaders = project.shaders.size();
    inputs.materials = project.materials.size();
    inputs.collections = project.variantCollections.size();
    inputs.virtualRoots = virtualRootsOf(project);
    inputs.stripping = strippingSummary(project.graphicsSettings);
    for (const project::ProjectShader& shader : project.shaders) {
        if (!shader.file.empty()) inputs.allShaderFiles.push_back(shader.file.generic_string());
    }
    ShaderResolver resolver(project, input, fileSystem, sourceMap);
    std::set<std::string> instanced;
    addRequests(project, resolver, sourceMap, inputs, instanced);
    SourceLocation settingsFile;
    if (project.graphicsSettings) {
        settingsFile.file = registerFile(sourceMap, project.graphicsSettings->path);
        ShaderResolver settingsResolver(project, input, fileSystem, sourceMap);
        for (const project::ShaderReference& reference : project.graphicsSettings->alwaysIncluded) {
            std::optional<std::string> file = settingsResolver.resolve(reference, settingsFile);
            if (file) inputs.demands[*file].alwaysIncluded = true;
        }
        settingsResolver.reportUnresolvedAsOneNote(sink, "always-included shaders");
    }
    resolver.reportUnresolved(sink);
    for (auto& [file, demand] : inputs.demands) {
        inputs.shaderFiles.push_back(file);
        demand.settingsRules =
            settingsStripRules(project.graphicsSettings, instanced.count(file) > 0, settingsFile);
    }
    return inputs;
}

namespace {

// Keywords of material request |index| that no pass of |shader| declares.
std::vector<std::string> undeclaredEverywhere(const frontend::LoadedShader& shader, size_t index) {
    std::vector<std::string> result;
    for (size_t p = 0; p < shader.passes.size(); ++p) {
        const variants::RequestProjection& projection =
            shader.passes[p].plan->selection->projections()[index];
        std::set<std::string> here(projection.undeclared.begin(), projection.undeclared.end());
        here.insert(projection.skipped.begin(), projection.skipped.end());
        if (p == 0) {
            result.assign(here.begin(), here.end());
        } else {
            std::erase_if(result, [&](const std::string& k) { return here.count(k) == 0; });
        }
    }
    return result;
}

void warnUndeclaredKeywords(const ProjectInputs& inputs, const frontend::LoadedShader& shader,
                            const frontend::ShaderDemand& demand, DiagnosticSink& sink) {
    if (shader.passes.empty()) return;
    for (size_t i = 0; i < demand.requests.size(); ++i) {
        std::vector<std::string> undeclared = undeclaredEverywhere(shader, i);
        if (undeclared.empty()) continue;
        auto file = inputs.requestFiles.find(demand.requests[i].name);
        SourceLocation where{file == inputs.requestFiles.end() ? kNoFile : file->second, 0, 0};
        std::string words;
        for (const std::string& keyword : undeclared) words += (words.empty() ? "" : " ") + keyword;
        sink.report({Severity::Warning, where,
                     "material keyword" + std::string(undeclared.size() > 1 ? "s " : " ") + words +
                         (undeclared.size() > 1 ? " are" : " is") + " not declared by shader \"" +
                         shader.ast.name + "\"; Unity ignores " +
                         (undeclared.size() > 1 ? "them" : "it"),
                     {}});
    }
}

}  // namespace

std::string projectSummary(const ProjectInputs& inputs) {
    return "Project " + inputs.root + ": " + std::to_string(inputs.projectShaders) +
           " shaders, " + std::to_string(inputs.shaderFiles.size()) + " in the build; " +
           std::to_string(inputs.materials) + " materials, " +
           std::to_string(inputs.collections) + " variant collections; stripping: " +
           inputs.stripping + "\n";
}

nlohmann::ordered_json projectJson(const ProjectInputs& inputs) {
    return {{"root", inputs.root},
            {"shaders", inputs.projectShaders},
            {"in_build", inputs.shaderFiles.size()},
            {"materials", inputs.materials},
            {"collections", inputs.collections},
            {"stripping", inputs.stripping}};
}

bool readUserStripRules(const std::string& path, includes::SourceMap& sourceMap,
                        DiagnosticSink& sink, std::vector<variants::StripRule>& rules) {
    auto specs = project::readStripRules(path, sink, [&sourceMap](const fs::path& file) {
        return registerFile(sourceMap, file);
    });
    if (!specs) return false;
    for (project::StripRuleSpec& spec : *specs) {
        rules.push_back({std::move(spec.name), spec.location, std::move(spec.shader),
                         std::move(spec.pass), spec.stage, std::move(spec.with),
                         std::move(spec.without)});
    }
    return true;
}

void planShaders(const ProjectInputs* inputs, const std::vector<variants::StripRule>& rules,
                 uint64_t limit, std::vector<frontend::LoadedShader>& shaders,
                 DiagnosticSink& sink) {
    frontend::ShaderDemand everything;
    everything.alwaysIncluded = true;  // no project: every declared variant
    frontend::ShaderDemand unused;     // a project shader no material names: the default only
    std::vector<uint64_t> removed(rules.size(), 0);
    for (frontend::LoadedShader& shader : shaders) {
        const frontend::ShaderDemand* demand = inputs ? &unused : &everything;
        if (inputs) {
            auto it = inputs->demands.find(shader.path);
            if (it != inputs->demands.end()) demand = &it->second;
        }
        for (frontend::LoadedPass& pass : shader.passes) {
            pass.plan = frontend::planPass(shader, pass, *demand, rules, limit);
            for (size_t r = 0; r < rules.size(); ++r) removed[r] += pass.plan->rulesRemoved[r];
        }
        if (inputs) warnUndeclaredKeywords(*inputs, shader, *demand, sink);
    }
    for (size_t r = 0; r < rules.size(); ++r) {
        if (removed[r] > 0) continue;
        sink.report({Severity::Warning, rules[r].location,
                     "strip rule '" + rules[r].name + "' removed no variant", {}});
    }
}

}  // namespace varc::cli
