// SPDX-License-Identifier: Apache-2.0
// loadProject: shader discovery and GUIDs, ordering, ignored folders, overlays, layouts.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "ProjectTestSupport.h"

namespace varc::project {
namespace {

using test::TempProject;
using ::testing::HasSubstr;

const std::string kGuidA = "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa";
const std::string kGuidB = "bbbbbbbbbbbbbbbbbbbbbbbbbbbbbbbb";

TEST(ProjectLoad, ShadersAreSortedByPathWithTheirMetaGuids) {
    TempProject project;
    project.write("Assets/Z/Last.shader", "Shader \"Z\" {}\n")
        .write("Assets/Z/Last.shader.meta", test::shaderMeta(kGuidB))
        .write("Assets/A/First.shader", "Shader \"A\" {}\n")
        .write("Assets/A/First.shader.meta", test::shaderMeta(kGuidA))
        .write("Assets/A/NoMeta.shader", "Shader \"N\" {}\n")
        .write("Assets/A/Common.cginc", "// not a shader\n");
    DiagnosticList diagnostics;
    Project loaded = loadProject(project.root(), diagnostics);
    EXPECT_EQ(loaded.layout, ProjectLayout::UnityProject);
    ASSERT_EQ(loaded.shaders.size(), 3u);
    EXPECT_EQ(loaded.shaders[0].path, "Assets/A/First.shader");
    EXPECT_EQ(loaded.shaders[0].guid, kGuidA);
    EXPECT_EQ(loaded.shaders[1].path, "Assets/A/NoMeta.shader");
    EXPECT_EQ(loaded.shaders[1].guid, "");
    EXPECT_EQ(loaded.shaders[2].path, "Assets/Z/Last.shader");
    EXPECT_EQ(loaded.shaders[2].file, project.root() / "Assets/Z/Last.shader");
    ASSERT_NE(loaded.findShaderByGuid(kGuidB), nullptr);
    EXPECT_EQ(loaded.findShaderByGuid(kGuidB)->path, "Assets/Z/Last.shader");
    EXPECT_EQ(loaded.findShaderByGuid("ffffffffffffffffffffffffffffffff"), nullptr);
    EXPECT_TRUE(diagnostics.diagnostics().empty());
}

TEST(ProjectLoad, FoldersUnityIgnoresAreSkippedUnlessAsked) {
    TempProject project;
    project.write("Assets/Kept.mat", test::materialYaml("Kept", test::builtinRef(46)))
        .write("Assets/Samples~/Hidden.mat", test::materialYaml("Hidden", test::builtinRef(46)))
        .write("Assets/.git/Dot.mat", test::materialYaml("Dot", test::builtinRef(46)));
    DiagnosticList diagnostics;
    EXPECT_EQ(loadProject(project.root(), diagnostics).materials.size(), 1u);
    LoadOptions options;
    options.includeUnityIgnored = true;
    Project all = loadProject(project.root(), diagnostics, options);
    ASSERT_EQ(all.materials.size(), 3u);
    EXPECT_EQ(all.materials[0].path, "Assets/.git/Dot.mat");
    EXPECT_EQ(all.materials[2].path, "Assets/Samples~/Hidden.mat");
}

TEST(ProjectLoad, ShaderSourceRootSuppliesShadersAndIncludes) {
    TempProject project;
    project.write("proj/Assets/Fx/Glow.shader.meta", test::shaderMeta(kGuidA))
        .write("proj/Assets/Glow.mat", test::materialYaml("Glow", test::projectShaderRef(kGuidA)))
        .write("src/Assets/Fx/Glow.shader", "Shader \"Fx/Glow\" {}\n")
        .write("src/Assets/Fx/Glow.cginc", "// include\n");
    LoadOptions options;
    options.shaderSourceRoots = {project.root() / "src"};
    DiagnosticList diagnostics;
    Project loaded = loadProject(project.root() / "proj", diagnostics, options);
    ASSERT_EQ(loaded.shaders.size(), 1u);
    EXPECT_EQ(loaded.shaders[0].path, "Assets/Fx/Glow.shader");
    EXPECT_EQ(loaded.shaders[0].file, project.root() / "src/Assets/Fx/Glow.shader");
    EXPECT_EQ(loaded.shaders[0].guid, kGuidA);
    ASSERT_EQ(loaded.materials.size(), 1u);
    EXPECT_EQ(loaded.materials[0].shader.shaderPath, "Assets/Fx/Glow.shader");
    EXPECT_EQ(loaded.includeRoots.resolve("Assets/Fx/Glow.cginc"),
              project.root() / "src/Assets/Fx/Glow.cginc");
    EXPECT_EQ(loaded.includeRoots.resolve("Assets/Fx/None.cginc"), std::nullopt);
    EXPECT_TRUE(diagnostics.diagnostics().empty());
}

TEST(ProjectLoad, MetaWithoutItsShaderStillNamesThePathAndWarns) {
    TempProject project;
    project.write("Assets/Gone.shader.meta", test::shaderMeta(kGuidA))
        .write("Assets/M.mat", test::materialYaml("M", test::projectShaderRef(kGuidA)));
    DiagnosticList diagnostics;
    Project loaded = loadProject(project.root(), diagnostics);
    ASSERT_EQ(loaded.shaders.size(), 1u);
    EXPECT_TRUE(loaded.shaders[0].file.empty());
    EXPECT_EQ(loaded.materials[0].shader.kind, ShaderReferenceKind::Project);
    auto texts = test::warningTexts(loaded, diagnostics);
    ASSERT_EQ(texts.size(), 1u);
    EXPECT_THAT(texts[0], HasSubstr("Gone.shader.meta: warning: no Gone.shader beside this .meta"));
}

TEST(ProjectLoad, FolderWithoutAssetsIsReadWhole) {
    TempProject project;
    project.write("Toon/Toon.shader", "Shader \"Toon\" {}\n")
        .write("Toon/Toon.shader.meta", test::shaderMeta(kGuidA))
        .write("Toon/Example.mat", test::materialYaml("Example", test::projectShaderRef(kGuidA)));
    DiagnosticList diagnostics;
    Project loaded = loadProject(project.root(), diagnostics);
    EXPECT_EQ(loaded.layout, ProjectLayout::AssetFolder);
    ASSERT_EQ(loaded.materials.size(), 1u);
    EXPECT_EQ(loaded.materials[0].path, "Toon/Example.mat");
    EXPECT_EQ(loaded.materials[0].shader.shaderPath, "Toon/Toon.shader");
    EXPECT_FALSE(loaded.graphicsSettings.has_value());
}

TEST(ProjectLoad, MissingRootIsAnError) {
    DiagnosticList diagnostics;
    Project loaded = loadProject("/nonexistent/varc/project", diagnostics);
    EXPECT_TRUE(diagnostics.hasErrors());
    EXPECT_TRUE(loaded.materials.empty());
}

TEST(ProjectLoad, FileIdsComeFromTheCallerWhenGiven) {
    TempProject project;
    project.write("Assets/Lost.mat", test::materialYaml("Lost", test::projectShaderRef(kGuidA)));
    std::vector<std::filesystem::path> registered;
    LoadOptions options;
    options.fileIdFor = [&](const std::filesystem::path& file) {
        registered.push_back(file);
        return static_cast<FileId>(100 + registered.size());
    };
    DiagnosticList diagnostics;
    Project loaded = loadProject(project.root(), diagnostics, options);
    ASSERT_EQ(diagnostics.diagnostics().size(), 1u);
    EXPECT_EQ(diagnostics.diagnostics()[0].location.file, 101u);
    ASSERT_EQ(registered.size(), 1u);
    EXPECT_EQ(registered[0], project.root() / "Assets/Lost.mat");
    EXPECT_TRUE(loaded.files.empty());
}

}  // namespace
}  // namespace varc::project
