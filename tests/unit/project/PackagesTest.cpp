// SPDX-License-Identifier: Apache-2.0
// Packages: embedded (package.json names), manifest.json with Library/PackageCache and file:.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "ProjectTestSupport.h"

namespace varc::project {
namespace {

using test::TempProject;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

TEST(Packages, EmbeddedPackageIsNamedByPackageJson) {
    TempProject project;
    project.folder("Assets")
        .write("Packages/fx-folder/package.json",
               "{\n\t\"name\": \"com.example.fx\",\n\t\"version\": \"1.0.0\"\n}\n")
        .write("Packages/fx-folder/Shaders/Fx.shader", "Shader \"Fx\" {}\n")
        .write("Packages/fx-folder/Shaders/Fx.cginc", "// fx\n")
        .write("Packages/manifest.json",
               "{ \"dependencies\": { \"com.example.fx\": \"2.0.0\" } }\n");
    DiagnosticList diagnostics;
    Project loaded = loadProject(project.root(), diagnostics);
    ASSERT_EQ(loaded.packages.size(), 1u);  // the embedded copy wins over the manifest's version
    EXPECT_EQ(loaded.packages[0].name, "com.example.fx");
    EXPECT_EQ(loaded.packages[0].source, PackageSource::Embedded);
    ASSERT_EQ(loaded.shaders.size(), 1u);
    EXPECT_EQ(loaded.shaders[0].path, "Packages/com.example.fx/Shaders/Fx.shader");
    EXPECT_EQ(loaded.includeRoots.resolve("Packages/com.example.fx/Shaders/Fx.cginc"),
              project.root() / "Packages/fx-folder/Shaders/Fx.cginc");
    EXPECT_EQ(loaded.includeRoots.resolve("Packages/fx-folder/Shaders/Fx.cginc"), std::nullopt);
    EXPECT_TRUE(diagnostics.diagnostics().empty());
}

TEST(Packages, ManifestEntriesComeFromThePackageCacheOrLocalFolders) {
    TempProject project;
    project.folder("Assets")
        .write("Packages/manifest.json",
               "{\n  \"dependencies\": {\n    \"com.unity.modules.physics\": \"1.0.0\",\n"
               "    \"com.example.cached\": \"3.1.0\",\n    \"com.example.hashed\": \"1.0.0\",\n"
               "    \"com.example.local\": \"file:../LocalPkg\"\n  }\n}\n")
        .write("Library/PackageCache/com.example.cached@3.1.0/Runtime/Cached.shader",
               "Shader \"C\" {}\n")
        .write("Library/PackageCache/com.example.cached@3.1.0/Runtime/Cached.shader.meta",
               test::shaderMeta("cccccccccccccccccccccccccccccccc"))
        .write("Library/PackageCache/com.example.hashed@a1b2c3d4/H.shader", "Shader \"H\" {}\n")
        .write("LocalPkg/L.shader", "Shader \"L\" {}\n");
    DiagnosticList diagnostics;
    Project loaded = loadProject(project.root(), diagnostics);
    ASSERT_EQ(loaded.packages.size(), 3u);
    EXPECT_EQ(loaded.packages[0].name, "com.example.cached");
    EXPECT_EQ(loaded.packages[0].source, PackageSource::Cache);
    EXPECT_EQ(loaded.packages[0].version, "3.1.0");
    EXPECT_EQ(loaded.packages[1].name, "com.example.hashed");
    EXPECT_EQ(loaded.packages[2].source, PackageSource::Local);
    EXPECT_THAT(loaded.packagesNotOnDisk, ElementsAre("com.unity.modules.physics"));
    ASSERT_EQ(loaded.shaders.size(), 3u);
    EXPECT_EQ(loaded.shaders[0].path, "Packages/com.example.cached/Runtime/Cached.shader");
    EXPECT_EQ(loaded.shaders[0].guid, "cccccccccccccccccccccccccccccccc");
    EXPECT_EQ(loaded.shaders[1].path, "Packages/com.example.hashed/H.shader");
    EXPECT_EQ(loaded.shaders[2].path, "Packages/com.example.local/L.shader");
    EXPECT_TRUE(diagnostics.diagnostics().empty());
}

TEST(Packages, MalformedManifestIsWarnedAndTheProjectStillLoads) {
    TempProject project;
    project.write("Assets/A.mat", test::materialYaml("A", test::builtinRef(46)))
        .write("Packages/manifest.json", "{ \"dependencies\": { \"x\": ");
    DiagnosticList diagnostics;
    Project loaded = loadProject(project.root(), diagnostics);
    EXPECT_EQ(loaded.materials.size(), 1u);
    auto texts = test::warningTexts(loaded, diagnostics);
    ASSERT_EQ(texts.size(), 1u);
    EXPECT_THAT(texts[0], HasSubstr("manifest.json:"));
    EXPECT_THAT(texts[0], HasSubstr("warning: malformed YAML"));
}

}  // namespace
}  // namespace varc::project
