// SPDX-License-Identifier: Apache-2.0
// ShaderVariantCollection files: shader references and their (passType, keywords) variants.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "ProjectTestSupport.h"

namespace varc::project {
namespace {

using test::TempProject;
using ::testing::ElementsAre;
using ::testing::HasSubstr;

const std::string kGuid = "deadbeefdeadbeefdeadbeefdeadbeef";

TEST(VariantCollection, EntriesKeepTheirShaderPassTypesAndKeywords) {
    TempProject project;
    project.write("Assets/Lit.shader", "Shader \"Lit\" {}\n")
        .write("Assets/Lit.shader.meta", test::shaderMeta(kGuid))
        .write("Assets/Warm.shadervariants.meta",
               test::shaderMeta("0badc0de0badc0de0badc0de0badc0de"))
        .write("Assets/Warm.shadervariants",
               test::kUnityHeader +
                   "--- !u!200 &20000000\nShaderVariantCollection:\n  m_Name: Warm\n  m_Shaders:\n"
                   "  - first: " +
                   test::builtinRef(46) +
                   "\n    second:\n      variants:\n"
                   "      - keywords: DIRECTIONAL _NORMALMAP\n        passType: 4\n"
                   "      - keywords: \n        passType: 8\n"
                   "  - first: " +
                   test::projectShaderRef(kGuid) +
                   "\n    second:\n"
                   "      variants: []\n");
    DiagnosticList diagnostics;
    Project loaded = loadProject(project.root(), diagnostics);
    ASSERT_EQ(loaded.variantCollections.size(), 1u);
    const ShaderVariantCollection& warm = loaded.variantCollections[0];
    EXPECT_EQ(warm.name, "Warm");
    EXPECT_EQ(warm.guid, "0badc0de0badc0de0badc0de0badc0de");
    ASSERT_EQ(warm.shaders.size(), 2u);
    EXPECT_EQ(warm.shaders[0].shader.kind, ShaderReferenceKind::Builtin);
    ASSERT_EQ(warm.shaders[0].variants.size(), 2u);
    EXPECT_EQ(warm.shaders[0].variants[0].passType, 4);
    EXPECT_THAT(warm.shaders[0].variants[0].keywords, ElementsAre("DIRECTIONAL", "_NORMALMAP"));
    EXPECT_EQ(warm.shaders[0].variants[1].passType, 8);
    EXPECT_TRUE(warm.shaders[0].variants[1].keywords.empty());
    EXPECT_EQ(warm.shaders[1].shader.shaderPath, "Assets/Lit.shader");
    EXPECT_TRUE(warm.shaders[1].variants.empty());
    EXPECT_TRUE(diagnostics.diagnostics().empty());
}

TEST(VariantCollection, VariantWithoutPassTypeIsSkippedWithAWarning) {
    TempProject project;
    project.write("Assets/Odd.shadervariants",
                  test::kUnityHeader +
                      "--- !u!200 &20000000\nShaderVariantCollection:\n  m_Shaders:\n"
                      "  - first: " +
                      test::builtinRef(46) +
                      "\n    second:\n      variants:\n"
                      "      - keywords: A\n        passType: four\n");
    DiagnosticList diagnostics;
    Project loaded = loadProject(project.root(), diagnostics);
    ASSERT_EQ(loaded.variantCollections.size(), 1u);
    ASSERT_EQ(loaded.variantCollections[0].shaders.size(), 1u);
    EXPECT_TRUE(loaded.variantCollections[0].shaders[0].variants.empty());
    auto texts = test::warningTexts(loaded, diagnostics);
    ASSERT_EQ(texts.size(), 1u);
    EXPECT_THAT(texts[0], HasSubstr("Odd.shadervariants:9:9: warning: variant without a readable"));
}

}  // namespace
}  // namespace varc::project
