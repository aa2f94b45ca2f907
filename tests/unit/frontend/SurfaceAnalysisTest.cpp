// SPDX-License-Identifier: Apache-2.0
// analyzeSurface and its text helpers: what the generator learns from the user's program.
#include <gtest/gtest.h>

#include "varc/frontend/SurfaceAnalysis.h"

namespace varc::frontend {
namespace {

using Members = std::vector<std::string>;

shaderlab::SurfaceProgram program(std::string function, std::string model) {
    shaderlab::SurfaceProgram surface;
    surface.function = std::move(function);
    surface.lightingModel = std::move(model);
    surface.pragma = {2, 5, 9};
    return surface;
}

constexpr std::string_view kLighting =
    "struct SurfaceOutput { fixed3 Albedo; fixed3 Normal; fixed Alpha; };\n"
    "inline fixed4 LightingLambert(SurfaceOutput s, UnityGI gi) { return 0; }\n"
    "inline void LightingLambert_GI(SurfaceOutput s, UnityGIInput data, inout UnityGI gi) {}\n"
    "half4 LightingToon(SurfaceOutput s, half3 lightDir, half3 viewDir, half atten) { return 0; }\n"
    "struct appdata_base { float4 vertex : POSITION; float3 normal : NORMAL; };\n";

TEST(SurfaceAnalysis, StructMembersSkipPreprocessorLinesSemanticsAndArrays) {
    std::string text =
        "struct Inputs { int no; };\n"
        "struct Input {\n  float2 uv_MainTex : TEXCOORD0;"
        "\n#ifdef A\n  float a[2], b;\n#endif\n  INTERNAL_DATA\n};";
    EXPECT_EQ(structMembers(text, "Input"), (Members{"uv_MainTex", "a", "b"}));
    EXPECT_EQ(structMembers(text, "Output"), std::nullopt);
}

TEST(SurfaceAnalysis, FunctionParametersComeFromTheDefinitionNotACall) {
    std::string text = "float4 x = surf(a, b);\nvoid surf (Input IN, inout SurfaceOutput o) : X {}";
    EXPECT_EQ(functionParameters(text, "surf"), (Members{"Input IN", "inout SurfaceOutput o"}));
    EXPECT_EQ(functionParameters("void f() {}", "f"), Members{});
    EXPECT_EQ(functionParameters("void f(int a);", "f"), std::nullopt);
}

TEST(SurfaceAnalysis, CommentsBecomeSpacesAndKeepLines) {
    EXPECT_EQ(withoutComments("a // b\nc /* d\ne */ f \"//\""), "a     \nc     \n     f \"//\"");
}

TEST(SurfaceAnalysis, ReadsInputOutputNormalWritesAndTheGiShape) {
    std::string text = std::string(kLighting) +
                       "struct Input { float2 uv_MainTex; float3 viewDir; INTERNAL_DATA };\n"
                       "void surf(Input IN, inout SurfaceOutput o) { o.Normal = float3(0,0,1); "
                       "o.Albedo = 1; }\n";
    DiagnosticList sink;
    auto facts = analyzeSurface(program("surf", "Lambert"), text, sink);
    ASSERT_TRUE(facts);
    EXPECT_EQ(facts->inputMembers, (Members{"uv_MainTex", "viewDir"}));
    EXPECT_TRUE(facts->inputHasInternalData);
    EXPECT_EQ(facts->outputType, "SurfaceOutput");
    EXPECT_EQ(facts->outputMembers, (Members{"Albedo", "Normal", "Alpha"}));
    EXPECT_TRUE(facts->writesNormal);
    EXPECT_EQ(facts->lighting, LightingShape::Gi);
    EXPECT_TRUE(facts->hasGiFunction);
    EXPECT_FALSE(facts->vertexWritesInput);
}

TEST(SurfaceAnalysis, ReadsALegacyShapeAndAVertexModifierWithItsInputType) {
    std::string text = std::string(kLighting) +
                       "struct Input { float y; };\n"
                       "void vert(inout appdata_base v, out Input o) { o.y = 0; }\n"
                       "void surf(Input IN, inout SurfaceOutput o) { if (o.Normal.x == 0) {} }\n";
    shaderlab::SurfaceProgram surface = program("surf", "Toon");
    surface.options.vertexFunction = "vert";
    DiagnosticList sink;
    auto facts = analyzeSurface(surface, text, sink);
    ASSERT_TRUE(facts);
    EXPECT_FALSE(facts->writesNormal);  // `==` reads it
    EXPECT_EQ(facts->lighting, LightingShape::LegacyViewDir);
    EXPECT_FALSE(facts->hasGiFunction);
    EXPECT_EQ(facts->vertexInputType, "appdata_base");
    EXPECT_EQ(facts->vertexInputMembers, (Members{"vertex", "normal"}));
    EXPECT_TRUE(facts->vertexWritesInput);
}

// `alphatest:_Cutoff` on the pragma line names the property without declaring it.
TEST(SurfaceAnalysis, PragmaLinesAndCommentsDoNotCountAsMentions) {
    std::string text = std::string(kLighting) +
                       "#pragma surface surf Lambert alphatest:_Cutoff\n"
                       "// float4 _MainTex_ST;\nfloat4 _Detail_ST;\n"
                       "struct Input { float y; };\n"
                       "void surf(Input IN, inout SurfaceOutput o) {}\n";
    DiagnosticList sink;
    auto facts = analyzeSurface(program("surf", "Lambert"), text, sink);
    ASSERT_TRUE(facts);
    EXPECT_FALSE(facts->mentions("_Cutoff"));
    EXPECT_FALSE(facts->mentions("_MainTex_ST"));
    EXPECT_TRUE(facts->mentions("_Detail_ST"));
}

TEST(SurfaceAnalysis, ReportsAMissingLightingFunctionAtThePragma) {
    std::string text = std::string(kLighting) +
                       "struct Input { float y; };\n"
                       "void surf(Input IN, inout SurfaceOutput o) {}\n";
    DiagnosticList sink;
    EXPECT_FALSE(analyzeSurface(program("surf", "Glass"), text, sink));
    ASSERT_EQ(sink.diagnostics().size(), 1u);
    EXPECT_EQ(sink.diagnostics()[0].location, (SourceLocation{2, 5, 9}));
    EXPECT_NE(sink.diagnostics()[0].message.find("'LightingGlass'"), std::string::npos);
}

TEST(SurfaceAnalysis, ReportsAMissingSurfaceFunction) {
    DiagnosticList sink;
    EXPECT_FALSE(analyzeSurface(program("paint", "Lambert"), kLighting, sink));
    ASSERT_EQ(sink.diagnostics().size(), 1u);
    EXPECT_EQ(sink.diagnostics()[0].message,
              "the surface function 'paint' of '#pragma surface' is not defined");
}

}  // namespace
}  // namespace varc::frontend
