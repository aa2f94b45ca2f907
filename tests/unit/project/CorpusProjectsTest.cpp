// SPDX-License-Identifier: Apache-2.0
// Every Unity project of ../shared/compat/projects (read in place, shaders from the overlays),
// checked against the figures of that folder's README.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "ProjectTestSupport.h"

namespace varc::project {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const fs::path kCompat = fs::path(VARC_SHARED_DIR) / "compat";

// The Unity project root inside a corpus folder: the folder itself, or the one subfolder that
// holds Assets/ (e.g. eangulee__UnityShader/UnityShader); the folder when it has no Assets/ at
// all (a package or shader collection repository).
fs::path projectRootOf(const fs::path& folder) {
    if (fs::is_directory(folder / "Assets")) return folder;
    std::vector<fs::path> nested;
    for (const auto& entry : fs::directory_iterator(folder)) {
        if (entry.is_directory() && fs::is_directory(entry.path() / "Assets")) {
            nested.push_back(entry.path());
        }
    }
    return nested.size() == 1 ? nested[0] : folder;
}

struct CorpusProject {
    std::string folder;
    Project project;
};

// Loads every corpus project; shaders come from compat/<path> and compat/surface/<path>.
std::vector<CorpusProject> loadCorpus(bool includeUnityIgnored, DiagnosticList& diagnostics) {
    std::vector<fs::path> folders;
    for (const auto& entry : fs::directory_iterator(kCompat / "projects")) {
        if (entry.is_directory()) folders.push_back(entry.path());
    }
    std::sort(folders.begin(), folders.end());
    std::vector<CorpusProject> loaded;
    for (const fs::path& folder : folders) {
        fs::path root = projectRootOf(folder);
        fs::path relative = root.lexically_relative(kCompat / "projects");
        LoadOptions options;
        options.includeUnityIgnored = includeUnityIgnored;
        options.shaderSourceRoots = {kCompat / relative, kCompat / "surface" / relative};
        loaded.push_back({folder.filename().string(), loadProject(root, diagnostics, options)});
    }
    return loaded;
}

class CorpusProjects : public ::testing::Test {
protected:
    void SetUp() override {
        if (!fs::is_directory(kCompat / "projects")) GTEST_SKIP() << "no " << kCompat;
    }
};

TEST_F(CorpusProjects, MaterialFiguresMatchTheReadme) {
    DiagnosticList diagnostics;
    std::vector<CorpusProject> corpus = loadCorpus(true, diagnostics);
    EXPECT_EQ(corpus.size(), 19u);  // lx2054807 has no project data
    size_t materials = 0, builtin = 0, unknown = 0, project = 0, withSource = 0, invalid = 0;
    size_t fromSurface = 0;  // shaders supplied by the second source root, compat/surface
    std::map<int64_t, size_t> builtinIds;
    for (const CorpusProject& entry : corpus) {
        for (const Material& material : entry.project.materials) {
            ++materials;
            switch (material.shader.kind) {
                case ShaderReferenceKind::Builtin:
                    ++builtin;
                    ++builtinIds[material.shader.asset.fileId];
                    break;
                case ShaderReferenceKind::UnknownGuid:
                    ++unknown;
                    break;
                case ShaderReferenceKind::Project: {
                    ++project;
                    const ProjectShader* shader =
                        entry.project.findShaderByGuid(material.shader.asset.guid);
                    if (shader && !shader->file.empty() && fs::is_regular_file(shader->file)) {
                        ++withSource;
                    }
                    if (shader &&
                        shader->file.string().find("/compat/surface/") != std::string::npos) {
                        ++fromSurface;
                    }
                    break;
                }
                case ShaderReferenceKind::Missing:
                    break;
            }
            if (!material.invalidKeywords.empty()) ++invalid;
        }
    }
    EXPECT_EQ(materials, 255u);
    EXPECT_EQ(builtin, 79u);
    EXPECT_EQ(unknown, 3u);
    EXPECT_EQ(project, 173u);
    EXPECT_EQ(withSource, 173u);  // every (a) shader is found in the shader source roots
    EXPECT_EQ(fromSurface, 11u);  // README: (a) in corpus by folder: main 162, surface 11
    EXPECT_EQ(invalid, 4u);
    EXPECT_EQ(builtinIds[46], 31u);
    EXPECT_EQ(builtinIds[10752], 9u);
    EXPECT_EQ(builtinIds[45], 2u);
}

TEST_F(CorpusProjects, WarningsAreTheThreeUnknownGuidsAndTheBinarySettings) {
    DiagnosticList diagnostics;
    std::vector<CorpusProject> corpus = loadCorpus(true, diagnostics);
    std::vector<std::string> messages;
    for (const Diagnostic& d : diagnostics.diagnostics()) {
        EXPECT_EQ(d.severity, Severity::Warning) << d.message;
        messages.push_back(d.message);
    }
    size_t unknownGuids = std::count_if(messages.begin(), messages.end(), [](const std::string& m) {
        return m.find("is defined by no .shader.meta") != std::string::npos;
    });
    size_t binary = std::count_if(messages.begin(), messages.end(), [](const std::string& m) {
        return m.find("binary-serialised") != std::string::npos;
    });
    EXPECT_EQ(unknownGuids, 3u);
    EXPECT_EQ(binary, 1u);  // Flafla2's GraphicsSettings.asset (Unity 5.4)
    EXPECT_EQ(messages.size(), 4u) << ::testing::PrintToString(messages);
}

TEST_F(CorpusProjects, UnityIgnoredSamplesFolderHoldsFourMaterials) {
    DiagnosticList diagnostics;
    std::vector<CorpusProject> corpus = loadCorpus(false, diagnostics);
    size_t materials = 0;
    for (const CorpusProject& entry : corpus) materials += entry.project.materials.size();
    // Chaser324's Packages/unity-wireframe/Samples~ (Unity does not import `~` folders).
    EXPECT_EQ(materials, 251u);
}

TEST_F(CorpusProjects, SlightlyMadAlwaysIncludesItsThreeShaders) {
    DiagnosticList diagnostics;
    std::vector<CorpusProject> corpus = loadCorpus(false, diagnostics);
    auto found = std::find_if(corpus.begin(), corpus.end(), [](const CorpusProject& entry) {
        return entry.folder == "SlightlyMad__VolumetricLights";
    });
    ASSERT_NE(found, corpus.end());
    ASSERT_TRUE(found->project.graphicsSettings.has_value());
    const GraphicsSettings& settings = *found->project.graphicsSettings;
    EXPECT_EQ(settings.serializedVersion, 5);
    EXPECT_EQ(settings.instancingStripping, std::nullopt);
    EXPECT_EQ(settings.lightmapKeepDirSeparate, true);
    std::vector<std::string> projectShaders;
    size_t builtins = 0;
    for (const ShaderReference& shader : settings.alwaysIncluded) {
        if (shader.kind == ShaderReferenceKind::Builtin) ++builtins;
        if (shader.kind != ShaderReferenceKind::Project) continue;
        projectShaders.push_back(shader.shaderPath);
        const ProjectShader* source = found->project.findShaderByGuid(shader.asset.guid);
        ASSERT_NE(source, nullptr);
        EXPECT_TRUE(fs::is_regular_file(source->file)) << source->file;
    }
    EXPECT_EQ(builtins, 6u);
    EXPECT_THAT(projectShaders, ::testing::ElementsAre("Assets/Shaders/BilateralBlur.shader",
                                                       "Assets/Shaders/BlitAdd.shader",
                                                       "Assets/Shaders/VolumetricLight.shader"));
}

TEST_F(CorpusProjects, VkevCustomPipelineAndEanguleeFogStripping) {
    DiagnosticList diagnostics;
    std::vector<CorpusProject> corpus = loadCorpus(false, diagnostics);
    std::map<std::string, const Project*> byFolder;
    for (const CorpusProject& entry : corpus) byFolder[entry.folder] = &entry.project;
    const Project* vkev = byFolder.at("VKev__Unity-BuiltInPipeline-Shaders-Code");
    ASSERT_TRUE(vkev->graphicsSettings && vkev->graphicsSettings->customRenderPipeline);
    EXPECT_EQ(vkev->graphicsSettings->customRenderPipeline->guid,
              "72a9f0222b701a34e94a3c8a129fd4bf");
    const Project* eangulee = byFolder.at("eangulee__UnityShader");
    ASSERT_TRUE(eangulee->graphicsSettings.has_value());
    EXPECT_EQ(eangulee->graphicsSettings->fogStripping, 1);
    EXPECT_EQ(eangulee->graphicsSettings->alwaysIncluded.size(), 9u);
    EXPECT_FALSE(byFolder.at("Flafla2__Generic-Raymarch-Unity")->graphicsSettings.has_value());
}

}  // namespace
}  // namespace varc::project
