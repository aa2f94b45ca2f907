// SPDX-License-Identifier: Apache-2.0
// generateSurfacePasses: which passes a surface program becomes, in order, with their state.
#include <gtest/gtest.h>

#include "varc/frontend/SurfacePasses.h"
#include "varc/shaderlab/ShaderLabParser.h"

namespace varc::frontend {
namespace {

constexpr std::string_view kLibrary =
    "struct SurfaceOutput { fixed3 Albedo; fixed3 Normal; fixed Alpha; };\n"
    "inline fixed4 LightingLambert(SurfaceOutput s, UnityGI gi) { return 0; }\n";

// Parses a shader whose one SubShader holds |body| and generates its passes from the program's
// own text plus kLibrary.
shaderlab::ShaderFile generate(const std::string& body, DiagnosticList& sink, bool& ok) {
    std::string text =
        "Shader \"S\" { SubShader { Tags { \"Queue\" = \"Geometry\" } " + body + " } }";
    auto shader = shaderlab::parseShaderLab(text, 1, sink);
    EXPECT_TRUE(shader);
    if (!shader) return {};
    ok = generateSurfacePasses(
        *shader,
        [](const shaderlab::Pass& pass) -> std::optional<std::string> {
            return std::string(kLibrary) + pass.surface->block.text;
        },
        sink);
    return std::move(*shader);
}

std::string program(std::string_view options) {
    return "CGPROGRAM\n#pragma surface surf Lambert " + std::string(options) +
           "\nstruct Input { float2 uv_MainTex; };\n"
           "void surf(Input IN, inout SurfaceOutput o) { o.Albedo = 1; }\nENDCG";
}

TEST(SurfacePasses, OpaqueProgramBecomesForwardBaseAndForwardAddInPlace) {
    DiagnosticList sink;
    bool ok = false;
    shaderlab::ShaderFile shader =
        generate("Pass { Name \"FIRST\" CGPROGRAM x ENDCG } Cull Off " + program(""), sink, ok);
    ASSERT_TRUE(ok);
    const std::vector<shaderlab::Pass>& passes = shader.subShaders.at(0).passes;
    ASSERT_EQ(passes.size(), 3u);
    EXPECT_EQ(passes[0].name, "FIRST");
    EXPECT_EQ(passes[1].name, "FORWARD");
    EXPECT_EQ(passes[1].lightMode(), "ForwardBase");
    EXPECT_FALSE(passes[1].state.blend);
    EXPECT_EQ(passes[1].state.cull.literal, "Off");  // the SubShader's state
    ASSERT_TRUE(passes[1].generated && passes[1].program);
    EXPECT_EQ(passes[1].generated->location, (SourceLocation{1, 2, 1}));
    EXPECT_FALSE(passes[1].surface);
    EXPECT_EQ(passes[2].lightMode(), "ForwardAdd");
    ASSERT_TRUE(passes[2].state.blend);
    EXPECT_EQ(passes[2].state.blend->src.literal, "One");
    EXPECT_EQ(passes[2].state.blend->dst.literal, "One");
    EXPECT_EQ(passes[2].state.zWrite.literal, "Off");
}

TEST(SurfacePasses, OptionsChooseThePassesAndTheBlending) {
    DiagnosticList sink;
    bool ok = false;
    shaderlab::ShaderFile shader = generate(program("alpha:fade noforwardadd addshadow"), sink, ok);
    ASSERT_TRUE(ok);
    const std::vector<shaderlab::Pass>& passes = shader.subShaders.at(0).passes;
    ASSERT_EQ(passes.size(), 2u);
    EXPECT_EQ(passes[0].lightMode(), "ForwardBase");
    ASSERT_TRUE(passes[0].state.blend);
    EXPECT_EQ(passes[0].state.blend->src.literal, "SrcAlpha");
    EXPECT_EQ(passes[0].state.blend->dst.literal, "OneMinusSrcAlpha");
    EXPECT_EQ(passes[0].state.zWrite.literal, "Off");
    EXPECT_EQ(passes[1].name, "ShadowCaster");
    EXPECT_EQ(passes[1].lightMode(), "ShadowCaster");
    EXPECT_FALSE(passes[1].state.blend);
}

TEST(SurfacePasses, AMissingLightingFunctionFailsAtThePragma) {
    DiagnosticList sink;
    bool ok = true;
    std::string body = program("");
    body.replace(body.find("Lambert"), 7, "Velvet");
    generate(body, sink, ok);
    EXPECT_FALSE(ok);
    ASSERT_EQ(sink.errorCount(), 1u);
    EXPECT_EQ(sink.diagnostics()[0].location, (SourceLocation{1, 2, 1}));
}

}  // namespace
}  // namespace varc::frontend
