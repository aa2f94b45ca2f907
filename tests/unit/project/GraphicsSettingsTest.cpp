// SPDX-License-Identifier: Apache-2.0
// GraphicsSettings.asset: always-included shaders, preloaded collections, stripping fields.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "ProjectTestSupport.h"

namespace varc::project {
namespace {

using test::TempProject;
using ::testing::HasSubstr;

const std::string kShaderGuid = "11112222333344445555666677778888";
const std::string kCollectionGuid = "99998888777766665555444433332222";

std::string settingsYaml(const std::string& fields) {
    return test::kUnityHeader + "--- !u!30 &1\nGraphicsSettings:\n  m_ObjectHideFlags: 0\n" +
           fields;
}

TEST(GraphicsSettings, AlwaysIncludedByFileIdAndGuidAndTheStrippingFields) {
    TempProject project;
    project.write("Assets/Fx.shader", "Shader \"Fx\" {}\n")
        .write("Assets/Fx.shader.meta", test::shaderMeta(kShaderGuid))
        .write("Assets/Warm.shadervariants.meta", test::shaderMeta(kCollectionGuid))
        .write(
            "Assets/Warm.shadervariants",
            test::kUnityHeader +
                "--- !u!200 &20000000\nShaderVariantCollection:\n  m_Name: Warm\n  m_Shaders: []\n")
        .write("ProjectSettings/GraphicsSettings.asset",
               settingsYaml("  serializedVersion: 12\n  m_AlwaysIncludedShaders:\n"
                            "  - " +
                            test::builtinRef(7) + "\n  - " + test::projectShaderRef(kShaderGuid) +
                            "\n"
                            "  m_PreloadedShaders:\n  - {fileID: 20000000, guid: " +
                            kCollectionGuid +
                            ", type: 2}\n"
                            "  m_LightmapStripping: 1\n  m_FogStripping: 0\n"
                            "  m_InstancingStripping: 2\n  m_LightmapKeepPlain: 1\n"
                            "  m_LightmapKeepShadowMask: 0\n  m_FogKeepExp2: 0\n"
                            "  m_CustomRenderPipeline: {fileID: 0}\n"));
    DiagnosticList diagnostics;
    Project loaded = loadProject(project.root(), diagnostics);
    ASSERT_TRUE(loaded.graphicsSettings.has_value());
    const GraphicsSettings& settings = *loaded.graphicsSettings;
    EXPECT_EQ(settings.serializedVersion, 12);
    ASSERT_EQ(settings.alwaysIncluded.size(), 2u);
    EXPECT_EQ(settings.alwaysIncluded[0].kind, ShaderReferenceKind::Builtin);
    EXPECT_EQ(settings.alwaysIncluded[0].asset.fileId, 7);
    EXPECT_EQ(settings.alwaysIncluded[1].kind, ShaderReferenceKind::Project);
    EXPECT_EQ(settings.alwaysIncluded[1].shaderPath, "Assets/Fx.shader");
    ASSERT_EQ(settings.preloaded.size(), 1u);
    EXPECT_EQ(settings.preloaded[0].collectionPath, "Assets/Warm.shadervariants");
    EXPECT_EQ(settings.lightmapStripping, 1);
    EXPECT_EQ(settings.fogStripping, 0);
    EXPECT_EQ(settings.instancingStripping, 2);
    EXPECT_EQ(settings.lightmapKeepPlain, true);
    EXPECT_EQ(settings.lightmapKeepShadowMask, false);
    EXPECT_EQ(settings.fogKeepExp2, false);
    EXPECT_EQ(settings.fogKeepLinear, std::nullopt);
    EXPECT_EQ(settings.customRenderPipeline, std::nullopt);
    EXPECT_TRUE(diagnostics.diagnostics().empty());
}

TEST(GraphicsSettings, CustomPipelineAndUnknownAlwaysIncludedGuid) {
    TempProject project;
    project.folder("Assets").write(
        "ProjectSettings/GraphicsSettings.asset",
        settingsYaml("  m_AlwaysIncludedShaders:\n  - " + test::projectShaderRef(kShaderGuid) +
                     "\n  m_CustomRenderPipeline: {fileID: 11400000, guid: " + kCollectionGuid +
                     ", type: 2}\n"));
    DiagnosticList diagnostics;
    Project loaded = loadProject(project.root(), diagnostics);
    ASSERT_TRUE(loaded.graphicsSettings.has_value());
    ASSERT_TRUE(loaded.graphicsSettings->customRenderPipeline.has_value());
    EXPECT_EQ(loaded.graphicsSettings->customRenderPipeline->fileId, 11400000);
    EXPECT_EQ(loaded.graphicsSettings->instancingStripping, std::nullopt);
    ASSERT_EQ(loaded.graphicsSettings->alwaysIncluded.size(), 1u);
    EXPECT_EQ(loaded.graphicsSettings->alwaysIncluded[0].kind, ShaderReferenceKind::UnknownGuid);
    auto texts = test::warningTexts(loaded, diagnostics);
    ASSERT_EQ(texts.size(), 1u);
    EXPECT_THAT(texts[0], HasSubstr("GraphicsSettings.asset:7:5: warning: always-included shader"));
}

TEST(GraphicsSettings, BinaryFileIsWarnedAndLeftUnread) {
    TempProject project;
    project.folder("Assets").write("ProjectSettings/GraphicsSettings.asset",
                                   std::string("\0\0\x0d\x0d\0\0\x11\x1c", 8) + "5.4.1f1");
    DiagnosticList diagnostics;
    Project loaded = loadProject(project.root(), diagnostics);
    EXPECT_FALSE(loaded.graphicsSettings.has_value());
    auto texts = test::warningTexts(loaded, diagnostics);
    ASSERT_EQ(texts.size(), 1u);
    EXPECT_THAT(texts[0], HasSubstr("GraphicsSettings.asset: warning: binary-serialised"));
}

}  // namespace
}  // namespace varc::project
