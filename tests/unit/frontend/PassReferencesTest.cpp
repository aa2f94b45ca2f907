// SPDX-License-Identifier: Apache-2.0
// UsePass and Fallback resolution: which passes a shader borrows, from where, and the warnings
// for references that lead nowhere.
#include <gtest/gtest.h>

#include "varc/frontend/PassReferences.h"
#include "varc/frontend/ShaderLoader.h"
#include "varc/includes/FileSystem.h"

namespace varc::frontend {
namespace {

using shaderlab::PassOrigin;

// A pass with a trivial program.
std::string passText(const std::string& name, const std::string& lightMode) {
    return "Pass { Name \"" + name + "\" Tags { \"LightMode\" = \"" + lightMode +
           "\" }\nCGPROGRAM\n#pragma vertex v\n#pragma fragment f\n"
           "float4 v(float4 p : POSITION) : SV_POSITION { return p; }\n"
           "float4 f() : SV_Target { return 0; }\nENDCG }\n";
}

class PassReferencesTest : public ::testing::Test {
protected:
    PassReferencesTest() {
        mFileSystem.add("builtin/fallback/VertexLit.shader",
                        "Shader \"Legacy Shaders/VertexLit\" { SubShader {\n" +
                            passText("ShadowCaster", "ShadowCaster") + "} }\n");
        mFileSystem.add(
            "builtin/fallback/Diffuse.shader",
            "Shader \"Legacy Shaders/Diffuse\" { Fallback \"Legacy Shaders/VertexLit\" }\n");
        mFileSystem.add("builtin/fallback/TransparentVertexLit.shader",
                        "Shader \"Legacy Shaders/Transparent/VertexLit\" { }\n");
    }

    // Loads |path| (already added) with the catalog of |inputs| and the built-in folder.
    std::optional<LoadedShader> load(const std::string& path, std::vector<std::string> inputs,
                                     std::vector<std::string> searchFiles = {}) {
        ShaderCatalog catalog(mFileSystem, mSourceMap, std::move(inputs), std::move(searchFiles),
                              "builtin");
        return loadShader(path, mFileSystem, mSourceMap, {}, mDiagnostics, &catalog);
    }

    std::string warnings() const {
        std::string text;
        for (const Diagnostic& diagnostic : mDiagnostics.diagnostics()) {
            if (diagnostic.severity == Severity::Warning) text += diagnostic.message + "\n";
        }
        return text;
    }

    includes::InMemoryFileSystem mFileSystem;
    includes::SourceMap mSourceMap;
    DiagnosticList mDiagnostics;
};

TEST_F(PassReferencesTest, ShaderWithoutCasterInheritsTheFallbackChainsCaster) {
    mFileSystem.add("a.shader", "Shader \"A\" { SubShader {\n" + passText("BASE", "ForwardBase") +
                                    "}\nFallback \"Diffuse\" }\n");
    auto shader = load("a.shader", {"a.shader"});
    ASSERT_TRUE(shader) << warnings();
    ASSERT_EQ(shader->passes.size(), 2u);
    const shaderlab::Pass& caster = *shader->passes[1].pass;
    EXPECT_EQ(caster.lightMode(), "ShadowCaster");
    EXPECT_EQ(caster.origin.kind, PassOrigin::Kind::Fallback);
    EXPECT_EQ(caster.origin.shader, "Legacy Shaders/VertexLit") << "the shader it is written in";
    EXPECT_EQ(mSourceMap.path(caster.origin.reference.file), "a.shader");
    EXPECT_EQ(shader->passes[1].index, 1u);
    EXPECT_EQ(describePass(shader->ast, caster, 1),
              "pass 1 \"ShadowCaster\" (LightMode ShadowCaster, from Fallback \"Legacy "
              "Shaders/VertexLit\") of shader \"A\"");
    EXPECT_EQ(warnings(), "");
}

TEST_F(PassReferencesTest, ShaderWithItsOwnCasterKeepsIt) {
    mFileSystem.add("a.shader", "Shader \"A\" { SubShader {\n" + passText("MINE", "ShadowCaster") +
                                    "}\nFallback \"VertexLit\" }\n");
    auto shader = load("a.shader", {"a.shader"});
    ASSERT_TRUE(shader);
    ASSERT_EQ(shader->passes.size(), 1u);
    EXPECT_EQ(shader->passes[0].pass->name, "MINE");
    EXPECT_EQ(shader->passes[0].pass->origin.kind, PassOrigin::Kind::Own);
}

TEST_F(PassReferencesTest, TransparentFallbackEndsTheChainWithoutCasterOrWarning) {
    mFileSystem.add("a.shader", "Shader \"A\" { SubShader {\n" + passText("BASE", "ForwardBase") +
                                    "}\nFallback \"Transparent/VertexLit\" }\n");
    auto shader = load("a.shader", {"a.shader"});
    ASSERT_TRUE(shader);
    EXPECT_EQ(shader->passes.size(), 1u);
    EXPECT_EQ(warnings(), "");
}

TEST_F(PassReferencesTest, UnknownFallbackWarnsThatTheShaderCastsNoShadows) {
    mFileSystem.add("a.shader", "Shader \"A\" { SubShader {\n" + passText("BASE", "ForwardBase") +
                                    "}\nFallback \"Nobody/Knows\" }\n");
    auto shader = load("a.shader", {"a.shader"});
    ASSERT_TRUE(shader);
    EXPECT_EQ(shader->passes.size(), 1u);
    EXPECT_NE(warnings().find("Fallback \"Nobody/Knows\" names no shader"), std::string::npos)
        << warnings();
    EXPECT_NE(warnings().find("casts no shadows"), std::string::npos);
}

TEST_F(PassReferencesTest, FallbackToAnotherInputAndCyclesStop) {
    mFileSystem.add("a.shader", "Shader \"A\" { SubShader {\n" + passText("BASE", "ForwardBase") +
                                    "}\nFallback \"B\" }\n");
    mFileSystem.add("b.shader", "Shader \"B\" { Fallback \"A\" }\n");
    auto shader = load("a.shader", {"a.shader", "b.shader"});
    ASSERT_TRUE(shader);
    EXPECT_EQ(shader->passes.size(), 1u);
    EXPECT_NE(warnings().find("returns to shader \"A\""), std::string::npos) << warnings();
}

TEST_F(PassReferencesTest, UsePassCopiesTheNamedPassWithoutCase) {
    mFileSystem.add("lib.shader", "Shader \"Lib/Outline\" { SubShader {\n" +
                                      passText("Outline", "Always") + "} }\n");
    mFileSystem.add(
        "a.shader",
        "Shader \"A\" { SubShader {\n" + passText("BASE", "ForwardBase") +
            "UsePass \"Lib/Outline/OUTLINE\"\nUsePass \"VertexLit/SHADOWCASTER\"\n} }\n");
    auto shader = load("a.shader", {"a.shader", "lib.shader"});
    ASSERT_TRUE(shader) << warnings();
    ASSERT_EQ(shader->passes.size(), 3u);
    EXPECT_EQ(shader->passes[1].pass->name, "Outline");
    EXPECT_EQ(shader->passes[1].pass->origin.kind, PassOrigin::Kind::UsePass);
    EXPECT_EQ(shader->passes[1].pass->origin.shader, "Lib/Outline");
    EXPECT_EQ(shader->passes[2].pass->lightMode(), "ShadowCaster");
    EXPECT_EQ(shader->passes[2].pass->origin.shader, "Legacy Shaders/VertexLit");
    EXPECT_EQ(warnings(), "") << "a UsePass caster means no Fallback caster is added";
}

TEST_F(PassReferencesTest, InputsComeBeforeProjectShadersWhichComeBeforeBuiltIns) {
    mFileSystem.add("project/VertexLit.shader",
                    "Shader \"Legacy Shaders/VertexLit\" { SubShader {\n" +
                        passText("ProjectCaster", "ShadowCaster") + "} }\n");
    mFileSystem.add("project/Outline.shader", "Shader \"Lib/Outline\" { SubShader {\n" +
                                                  passText("Outline", "Always") + "} }\n");
    mFileSystem.add("a.shader",
                    "Shader \"A\" { SubShader {\n" + passText("BASE", "ForwardBase") +
                        "UsePass \"Lib/Outline/OUTLINE\"\n}\nFallback \"VertexLit\" }\n");
    auto shader =
        load("a.shader", {"a.shader"}, {"project/VertexLit.shader", "project/Outline.shader"});
    ASSERT_TRUE(shader) << warnings();
    ASSERT_EQ(shader->passes.size(), 3u);
    EXPECT_EQ(shader->passes[1].pass->name, "Outline");
    EXPECT_EQ(shader->passes[2].pass->name, "ProjectCaster") << "the project's shader wins";
}

TEST_F(PassReferencesTest, UsePassThatLeadsNowhereIsSkippedWithAWarning) {
    mFileSystem.add("a.shader", "Shader \"A\" { SubShader {\n" + passText("BASE", "ForwardBase") +
                                    "UsePass \"VertexLit/NOPE\"\nUsePass \"Missing/PASS\"\n"
                                    "UsePass \"NOSLASH\"\n} }\n");
    auto shader = load("a.shader", {"a.shader"});
    ASSERT_TRUE(shader);
    EXPECT_EQ(shader->passes.size(), 1u);
    std::string text = warnings();
    EXPECT_NE(text.find("has no pass named \"NOPE\""), std::string::npos) << text;
    EXPECT_NE(text.find("no shader named \"Missing\""), std::string::npos) << text;
    EXPECT_NE(text.find("names no pass"), std::string::npos) << text;
}

TEST_F(PassReferencesTest, WithoutCatalogReferencesStayUnresolved) {
    mFileSystem.add("a.shader",
                    "Shader \"A\" { SubShader {\n" + passText("BASE", "ForwardBase") +
                        "UsePass \"VertexLit/SHADOWCASTER\"\n}\nFallback \"VertexLit\" }\n");
    auto shader = loadShader("a.shader", mFileSystem, mSourceMap, {}, mDiagnostics);
    ASSERT_TRUE(shader);
    EXPECT_EQ(shader->passes.size(), 1u);
}

}  // namespace
}  // namespace varc::frontend
