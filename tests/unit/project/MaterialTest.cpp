// SPDX-License-Identifier: Apache-2.0
// Materials: both keyword serialisations, shader references of every kind, bad files.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "ProjectTestSupport.h"
#include "varc/project/BuiltinShaders.h"

namespace varc::project {
namespace {

using test::materialYaml;
using test::TempProject;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

const std::string kGuid = "0123456789abcdef0123456789abcdef";

TEST(Material, LegacyKeywordStringWrappedOntoContinuationLinesIsJoined) {
    TempProject project;
    project.write("Assets/Rock.mat",
                  materialYaml("Rock", test::builtinRef(46),
                               "  m_ShaderKeywords: _ALPHATEST_ON _GLOSSYREFLECTIONS_OFF\n"
                               "    _SPECULARHIGHLIGHTS_OFF\n  m_LightmapFlags: 4\n"));
    DiagnosticList diagnostics;
    Project loaded = loadProject(project.root(), diagnostics);
    ASSERT_EQ(loaded.materials.size(), 1u);
    const Material& rock = loaded.materials[0];
    EXPECT_EQ(rock.path, "Assets/Rock.mat");
    EXPECT_EQ(rock.name, "Rock");
    EXPECT_THAT(rock.legacyKeywords,
                ElementsAre("_ALPHATEST_ON", "_GLOSSYREFLECTIONS_OFF", "_SPECULARHIGHLIGHTS_OFF"));
    EXPECT_EQ(rock.keywordForm(), KeywordForm::LegacyString);
    EXPECT_TRUE(diagnostics.diagnostics().empty());
}

TEST(Material, ValidAndInvalidListsAreKeptApart) {
    TempProject project;
    project.write("Assets/A.mat", materialYaml("A", test::builtinRef(46),
                                               "  m_ValidKeywords:\n  - _NORMALMAP\n  - _EMISSION\n"
                                               "  m_InvalidKeywords:\n  - _OLD_ON\n"
                                               "  m_EnableInstancingVariants: 1\n"));
    DiagnosticList diagnostics;
    Project loaded = loadProject(project.root(), diagnostics);
    ASSERT_EQ(loaded.materials.size(), 1u);
    const Material& a = loaded.materials[0];
    EXPECT_EQ(a.keywordForm(), KeywordForm::Lists);
    EXPECT_THAT(a.validKeywords, ElementsAre("_NORMALMAP", "_EMISSION"));
    EXPECT_THAT(a.invalidKeywords, ElementsAre("_OLD_ON"));
    EXPECT_THAT(a.enabledKeywords(), ElementsAre("_EMISSION", "_NORMALMAP"));
    EXPECT_THAT(a.keywordsIncludingInvalid(), ElementsAre("_EMISSION", "_NORMALMAP", "_OLD_ON"));
    EXPECT_TRUE(a.enableInstancingVariants);
}

TEST(Material, EmptyListsAndLoneUnderscoreGiveNoKeywords) {
    TempProject project;
    project.write("Assets/Empty.mat",
                  materialYaml("Empty", test::builtinRef(46),
                               "  m_ValidKeywords: []\n  m_InvalidKeywords: []\n"));
    project.write("Assets/Under.mat",
                  materialYaml("Under", test::builtinRef(46), "  m_ShaderKeywords: _ FOG_ON\n"));
    DiagnosticList diagnostics;
    Project loaded = loadProject(project.root(), diagnostics);
    ASSERT_EQ(loaded.materials.size(), 2u);
    EXPECT_EQ(loaded.materials[0].path, "Assets/Empty.mat");
    EXPECT_TRUE(loaded.materials[0].enabledKeywords().empty());
    EXPECT_EQ(loaded.materials[0].keywordForm(), KeywordForm::Lists);
    EXPECT_THAT(loaded.materials[1].legacyKeywords, ElementsAre("FOG_ON"));
    EXPECT_FALSE(loaded.materials[1].enableInstancingVariants);
}

TEST(Material, ProjectGuidResolvesToTheShaderPath) {
    TempProject project;
    project.write("Assets/Shaders/Rock.shader", "Shader \"Custom/Rock\" {}\n")
        .write("Assets/Shaders/Rock.shader.meta", test::shaderMeta(kGuid))
        .write("Assets/Rock.mat", materialYaml("Rock", test::projectShaderRef(kGuid)));
    DiagnosticList diagnostics;
    Project loaded = loadProject(project.root(), diagnostics);
    ASSERT_EQ(loaded.materials.size(), 1u);
    EXPECT_EQ(loaded.materials[0].shader.kind, ShaderReferenceKind::Project);
    EXPECT_EQ(loaded.materials[0].shader.shaderPath, "Assets/Shaders/Rock.shader");
    EXPECT_EQ(loaded.materials[0].shader.asset.fileId, kShaderMainFileId);
    EXPECT_TRUE(diagnostics.diagnostics().empty());
}

TEST(Material, UnknownGuidIsWarnedAtTheShaderLine) {
    TempProject project;
    project.write("Assets/Lost.mat", materialYaml("Lost", test::projectShaderRef(kGuid)));
    DiagnosticList diagnostics;
    Project loaded = loadProject(project.root(), diagnostics);
    ASSERT_EQ(loaded.materials.size(), 1u);
    EXPECT_EQ(loaded.materials[0].shader.kind, ShaderReferenceKind::UnknownGuid);
    EXPECT_EQ(loaded.materials[0].shader.asset.guid, kGuid);
    auto texts = test::warningTexts(loaded, diagnostics);
    ASSERT_EQ(texts.size(), 1u);
    // m_Shader is line 7 of the file; its value starts in column 13.
    EXPECT_THAT(texts[0], HasSubstr("Assets/Lost.mat:7:13: warning: material 'Lost'"));
    EXPECT_THAT(texts[0], HasSubstr(kGuid));
}

TEST(Material, BuiltinReferenceIsNamedFromTheTable) {
    TempProject project;
    project.write("Assets/Std.mat", materialYaml("Std", test::builtinRef(46)));
    DiagnosticList diagnostics;
    Project loaded = loadProject(project.root(), diagnostics);
    ASSERT_EQ(loaded.materials.size(), 1u);
    const ShaderReference& shader = loaded.materials[0].shader;
    EXPECT_EQ(shader.kind, ShaderReferenceKind::Builtin);
    EXPECT_EQ(shader.asset.fileId, 46);
    EXPECT_EQ(builtinShaderName(shader.asset.guid, shader.asset.fileId), "Standard");
}

TEST(Material, NullOrAbsentShaderIsMissingWithAWarning) {
    TempProject project;
    project.write("Assets/Null.mat", materialYaml("Nothing", "{fileID: 0}"))
        .write("Assets/NoField.mat", test::kUnityHeader +
                                         "--- !u!21 &2100000\nMaterial:\n  m_Name: NoField\n"
                                         "  m_ShaderKeywords: A\n");
    DiagnosticList diagnostics;
    Project loaded = loadProject(project.root(), diagnostics);
    ASSERT_EQ(loaded.materials.size(), 2u);
    EXPECT_EQ(loaded.materials[0].shader.kind, ShaderReferenceKind::Missing);
    EXPECT_EQ(loaded.materials[1].shader.kind, ShaderReferenceKind::Missing);
    EXPECT_THAT(loaded.materials[0].legacyKeywords, ElementsAre("A"));
    auto texts = test::warningTexts(loaded, diagnostics);
    ASSERT_EQ(texts.size(), 2u);
    EXPECT_THAT(texts[0],
                HasSubstr("NoField.mat:5:3: warning: material 'NoField' has no readable"));
    EXPECT_THAT(texts[1], HasSubstr("Null.mat:7:13: warning: material 'Nothing' names no shader"));
}

TEST(Material, BinaryMaterialIsSkippedWithAWarningNamingTheFile) {
    TempProject project;
    project
        .write("Assets/Binary.mat", std::string("\0\0\x0d\x0d\0\0\x11\x1c\0\0\0\x0f", 12) +
                                        "5.4.1f1" + std::string(1, '\0'))
        .write("Assets/Text.mat", materialYaml("Text", test::builtinRef(46)));
    DiagnosticList diagnostics;
    Project loaded = loadProject(project.root(), diagnostics);
    ASSERT_EQ(loaded.materials.size(), 1u);
    EXPECT_EQ(loaded.materials[0].name, "Text");
    auto texts = test::warningTexts(loaded, diagnostics);
    ASSERT_EQ(texts.size(), 1u);
    EXPECT_THAT(texts[0], HasSubstr("Assets/Binary.mat: warning: binary-serialised Unity asset"));
}

TEST(Material, MalformedYamlIsWarnedWithItsPositionAndTheRestStillLoads) {
    TempProject project;
    project
        .write("Assets/Bad.mat", test::kUnityHeader +
                                     "--- !u!21 &2100000\nMaterial:\n  m_Shader: {fileID: 46, "
                                     "guid: 0000000000000000f000000000000000\n  m_Name: x\n")
        .write("Assets/Good.mat", materialYaml("Good", test::builtinRef(46)));
    DiagnosticList diagnostics;
    Project loaded = loadProject(project.root(), diagnostics);
    ASSERT_EQ(loaded.materials.size(), 1u);
    EXPECT_EQ(loaded.materials[0].name, "Good");
    auto texts = test::warningTexts(loaded, diagnostics);
    ASSERT_EQ(texts.size(), 1u);
    EXPECT_THAT(texts[0], ::testing::MatchesRegex(".*Assets/Bad\\.mat:[0-9]+:[0-9]+: warning: "
                                                  "malformed YAML.*"));
}

TEST(Material, DeeplyNestedYamlIsWarnedNotACrash) {
    TempProject project;
    project.write("Assets/Deep.mat", test::kUnityHeader +
                                         "--- !u!21 &2100000\nMaterial:\n  m_Name: " +
                                         std::string(100000, '[') + "\n");
    DiagnosticList diagnostics;
    Project loaded = loadProject(project.root(), diagnostics);
    EXPECT_TRUE(loaded.materials.empty());
    auto texts = test::warningTexts(loaded, diagnostics);
    ASSERT_EQ(texts.size(), 1u);
    EXPECT_THAT(texts[0], HasSubstr("Deep.mat"));
    EXPECT_THAT(texts[0], HasSubstr("malformed YAML"));
}

TEST(Material, EveryTruncationOfAMaterialLoadsWithoutThrowing) {
    std::string full = materialYaml("Cut", test::builtinRef(46),
                                    "  m_ValidKeywords:\n  - _A\n  m_InvalidKeywords: [_B]\n"
                                    "  m_EnableInstancingVariants: 1\n");
    TempProject project;
    for (size_t length = 0; length <= full.size(); length += 3) {
        project.write("Assets/Cut.mat", full.substr(0, length));
        DiagnosticList diagnostics;
        Project loaded = loadProject(project.root(), diagnostics);
        EXPECT_LE(loaded.materials.size(), 1u) << length;
    }
}

}  // namespace
}  // namespace varc::project
