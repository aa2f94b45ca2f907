// SPDX-License-Identifier: Apache-2.0
// glslang in-process: DX9-style HLSL and legacy GLSL compile to valid Vulkan SPIR-V, and the
// #line convention varc emits maps errors back to the right original line.
#include <gtest/gtest.h>

#include "varc/driver/GlslLegacyPreamble.h"
#include "varc/driver/GlslangFrontend.h"
#include "varc/driver/GlslangLogParser.h"
#include "varc/driver/SpirvOptimizer.h"
#include "varc/variants/PassKeywords.h"

namespace varc::driver {
namespace {

constexpr const char* kHlsl = R"(#line 1 0
sampler2D _MainTex;
samplerCUBE _Cube;
float4 _Tint;
struct VertexData { float4 position : POSITION; float2 uv : TEXCOORD0; };
struct Interpolators { float4 position : SV_POSITION; float2 uv : TEXCOORD0; };
Interpolators vert(VertexData v) {
    Interpolators i;
    i.position = v.position * _Tint;
    i.uv = v.uv;
    return i;
}
float4 frag(Interpolators i) : SV_Target {
    float4 c = tex2Dbias(_MainTex, float4(i.uv, 0, -1));
    return c + texCUBEbias(_Cube, float4(i.uv, 1, 0)) * _Tint;
}
)";

std::vector<uint32_t> compileValid(const FrontendInput& input) {
    CompileOutput compiled = compileProgram(input);
    EXPECT_TRUE(compiled.ok) << compiled.log;
    SpirvResult optimized = optimizeSpirv(compiled.spirv, OptimizationLevel::Performance);
    EXPECT_TRUE(optimized.ok) << optimized.message;
    auto invalid = validateSpirv(optimized.spirv);
    EXPECT_FALSE(invalid.has_value()) << *invalid;
    return optimized.spirv;
}

TEST(GlslangFrontend, CompilesDx9StyleHlslStagesToValidSpirv) {
    for (auto [stage, entry] :
         {std::pair{Stage::Vertex, "vert"}, std::pair{Stage::Fragment, "frag"}}) {
        std::vector<uint32_t> spirv =
            compileValid({kHlsl, "", shaderlab::ProgramLanguage::Cg, stage, entry});
        ASSERT_GT(spirv.size(), 5u);
        EXPECT_EQ(spirv[0], 0x07230203u);  // SPIR-V magic
    }
}

TEST(GlslangFrontend, PreprocessingResolvesPreambleDefinesAndKeepsLineDirectives) {
    std::string source = "#line 7 2\n#ifdef POINT\nfloat point;\n#else\nfloat other;\n#endif\n";
    PreprocessOutput pre = preprocessProgram(
        {source, "#define POINT 1\n", shaderlab::ProgramLanguage::Hlsl, Stage::Vertex, "v"});
    ASSERT_TRUE(pre.ok) << pre.log;
    EXPECT_NE(pre.text.find("float point;"), std::string::npos);
    EXPECT_EQ(pre.text.find("float other;"), std::string::npos);
    EXPECT_NE(pre.text.find("#line 7 2"), std::string::npos);
}

// Pins glslang's reading of `#line N F` for HLSL: the next line is line N of file F.
TEST(GlslangFrontend, HlslLineDirectiveNumbersTheNextLine) {
    includes::SourceMap sourceMap;
    sourceMap.addFile("root.shader", "");
    sourceMap.addFile("lib.cginc", "a\nb\nc\nd\nfloat4 f() { return missingThing; }\n");
    std::string source =
        "#line 5 1\nfloat4 f() { return missingThing; }\n"
        "float4 v() : SV_Position { return f(); }\n";
    CompileOutput compiled =
        compileProgram({source, "", shaderlab::ProgramLanguage::Hlsl, Stage::Vertex, "v"});
    ASSERT_FALSE(compiled.ok);
    auto diagnostics = parseGlslangLog(compiled.log, sourceMap);
    ASSERT_FALSE(diagnostics.empty()) << compiled.log;
    EXPECT_EQ(diagnostics[0].location, (SourceLocation{1, 5, 21})) << compiled.log;
}

// Pins the legacy GLSL convention: after toGlslLineConvention, the same mapping holds.
TEST(GlslangFrontend, LegacyGlslLineDirectiveMapsAfterConversion) {
    includes::SourceMap sourceMap;
    sourceMap.addFile("root.shader", "");
    sourceMap.addFile("lib.glslinc", "a\nb\nvoid main() { gl_FragColor = missingThing; }\n");
    std::string source =
        toGlslLineConvention("#line 3 1\nvoid main() { gl_FragColor = missingThing; }\n");
    std::string preamble = legacyGlslPreamble(source, Stage::Fragment);
    CompileOutput compiled = compileProgram(
        {source, preamble, shaderlab::ProgramLanguage::Glsl, Stage::Fragment, "main"});
    ASSERT_FALSE(compiled.ok);
    auto diagnostics = parseGlslangLog(compiled.log, sourceMap);
    ASSERT_FALSE(diagnostics.empty()) << compiled.log;
    EXPECT_EQ(diagnostics[0].location, (SourceLocation{1, 3, 30})) << compiled.log;
}

TEST(GlslangFrontend, CompilesLegacyGlslWithLooseUniformsAndVaryings) {
    std::string source = R"(#line 1 0
uniform vec4 _Color;
uniform mat4 _Object2World;
varying vec4 position;
#ifdef VERTEX
void main() {
    position = _Object2World * gl_Vertex;
    gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
}
#endif
#ifdef FRAGMENT
void main() { gl_FragColor = _Color * position + gl_LightModel.ambient; }
#endif
)";
    for (auto stage : {Stage::Vertex, Stage::Fragment}) {
        std::string text = toGlslLineConvention(source);
        std::string preamble =
            std::string(stage == Stage::Vertex ? "#define VERTEX 1\n" : "#define FRAGMENT 1\n") +
            legacyGlslPreamble(text, stage);
        PreprocessOutput pre =
            preprocessProgram({text, preamble, shaderlab::ProgramLanguage::Glsl, stage, "main"});
        ASSERT_TRUE(pre.ok) << pre.log;
        compileValid({pre.text, "", shaderlab::ProgramLanguage::Glsl, stage, "main"});
    }
}

}  // namespace
}  // namespace varc::driver
