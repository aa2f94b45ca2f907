// SPDX-License-Identifier: Apache-2.0
// Tests for StagePruner: reachability, $Global grouping, #line mapping, determinism, fallbacks.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "varc/frontend/StagePruner.h"

namespace varc::frontend {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::Not;

// Drops the newline that follows `R"(` so programs can start on their own line.
std::string program(std::string_view text) {
    if (!text.empty() && text.front() == '\n') text.remove_prefix(1);
    return std::string(text);
}

std::string_view trim(std::string_view s) {
    const size_t begin = s.find_first_not_of(" \t");
    return begin == std::string_view::npos
               ? ""
               : s.substr(begin, s.find_last_not_of(" \t\r") + 1 - begin);
}

std::vector<std::string> splitLines(std::string_view text) {
    std::vector<std::string> lines;
    std::istringstream in{std::string(text)};
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

struct LineKey {
    std::string source;  // "" until a #line names one
    uint64_t line = 0;
    auto operator<=>(const LineKey&) const = default;
};

// Every non-blank, non-directive line of |text| with the (source, line) its #line directives
// give it, reading `#line N [M]` as naming the next line (glslang's HLSL / GLSL >= 330 rule);
// before any #line, lines count physically from 1.
std::vector<std::pair<LineKey, std::string>> numberedCodeLines(std::string_view text) {
    std::vector<std::pair<LineKey, std::string>> result;
    LineKey next{"", 1};
    for (const std::string& raw : splitLines(text)) {
        const std::string_view line = trim(raw);
        if (line.starts_with("#line")) {
            std::istringstream directive{std::string(line.substr(5))};
            std::string source;
            directive >> next.line >> source;
            if (!source.empty()) next.source = source;
            continue;
        }
        if (!line.empty() && line.front() != '#') result.emplace_back(next, std::string(line));
        ++next.line;
    }
    return result;
}

// True when the words of |kept| occur, in order, inside |original|.
bool isPieceOf(std::string_view kept, std::string_view original) {
    std::istringstream words{std::string(kept)};
    size_t at = 0;
    for (std::string word; words >> word;) {
        at = original.find(word, at);
        if (at == std::string_view::npos) return false;
        at += word.size();
    }
    return true;
}

// Each code line of |pruned| must map (through its #lines) to the input line it came from.
void expectLinesMapToOrigin(std::string_view input, std::string_view pruned) {
    std::map<LineKey, std::string> original;
    for (auto& [key, line] : numberedCodeLines(input)) {
        ASSERT_TRUE(original.emplace(key, line).second) << "ambiguous input line " << key.line;
    }
    const auto kept = numberedCodeLines(pruned);
    ASSERT_FALSE(kept.empty());
    for (const auto& [key, line] : kept) {
        const auto found = original.find(key);
        ASSERT_NE(found, original.end()) << "'" << line << "' maps to a line with no code";
        EXPECT_TRUE(isPieceOf(line, found->second))
            << "'" << line << "' maps to " << key.source << ":" << key.line << " which is '"
            << found->second << "'";
    }
}

PruneResult pruneHlsl(std::string_view text, std::string_view entry) {
    return pruneToEntryPoint(text, entry, ShaderDialect::Hlsl);
}

const std::string kTwoStages = program(R"(
#line 1 0
float4x4 M;
sampler2D _MainTex;
static const float kFragScale = 2;
struct V2F { float4 pos : SV_POSITION; float2 uv : TEXCOORD0; };
float4 shade(float2 uv) { return tex2D(_MainTex, uv) * kFragScale; }
V2F vert(float4 p : POSITION) {
    V2F o;
    o.pos = mul(M, p);
    o.uv = p.xy;
    return o;
}
float4 frag(V2F i) : SV_Target { return shade(i.uv); }
)");

TEST(StagePruner, VertexEntryDropsFragmentOnlyFunctionsGlobalsAndTextures) {
    const PruneResult result = pruneHlsl(kTwoStages, "vert");
    ASSERT_TRUE(result.pruned);
    EXPECT_THAT(result.keptFunctions, ElementsAre("vert"));
    EXPECT_EQ(result.text, program(R"(
#line 1 0
float4x4 M;
#line 4 0
struct V2F { float4 pos : SV_POSITION; float2 uv : TEXCOORD0; };
#line 6 0
V2F vert(float4 p : POSITION) {
    V2F o;
    o.pos = mul(M, p);
    o.uv = p.xy;
    return o;
}
)"));
    expectLinesMapToOrigin(kTwoStages, result.text);
}

TEST(StagePruner, FragmentEntryKeepsItsHelperTexturesAndConstants) {
    const PruneResult result = pruneHlsl(kTwoStages, "frag");
    ASSERT_TRUE(result.pruned);
    EXPECT_THAT(result.keptFunctions, ElementsAre("shade", "frag"));
    EXPECT_THAT(result.text, HasSubstr("sampler2D _MainTex;\nstatic const float kFragScale = 2;"));
    EXPECT_THAT(result.text, Not(HasSubstr("float4x4 M;")));  // the only loose uniform, unused
    EXPECT_THAT(result.text, Not(HasSubstr("vert")));
}

TEST(StagePruner, KeepsTransitiveCallsOnly) {
    const std::string input = program(R"(
#line 1 0
float c(float x) { return x * 2; }
float b(float x) { return c(x) + 1; }
float a(float x) { return b(x); }
float unused(float x) { return c(x); }
float4 vert(float4 p : POSITION) : SV_POSITION { return p * a(p.x); }
)");
    const PruneResult result = pruneHlsl(input, "vert");
    EXPECT_THAT(result.keptFunctions, ElementsAre("c", "b", "a", "vert"));
    EXPECT_THAT(result.text, Not(HasSubstr("unused")));
}

TEST(StagePruner, KeepsEveryOverloadAndPrototypeOfACalledName) {
    const std::string input = program(R"(
#line 1 0
float3 tint(float3 c);
float3 tint(float3 c) { return c * 0.5; }
float4 tint(float4 c) { return c * 0.25; }
float2 other(float2 c) { return c; }
float4 other(float4 c) { return c; }
float4 vert(float4 p : POSITION) : SV_POSITION { return tint(p); }
)");
    const PruneResult result = pruneHlsl(input, "vert");
    EXPECT_THAT(result.keptFunctions, ElementsAre("tint", "vert"));
    EXPECT_THAT(result.text, HasSubstr("float3 tint(float3 c);\nfloat3 tint(float3 c) {"));
    EXPECT_THAT(result.text, HasSubstr("float4 tint(float4 c) {"));
    EXPECT_THAT(result.text, Not(HasSubstr("other")));
}

TEST(StagePruner, KeepsStructTypesThroughSignaturesAndMembers) {
    const std::string input = program(R"(
#line 1 0
struct Inner { float4 value; };
struct Input { Inner inner; float4 pos : POSITION; };
struct Result { float4 pos : SV_POSITION; };
struct FragOnly { float4 color; };
typedef Inner InnerAlias;
typedef FragOnly FragAlias;
Result make(InnerAlias v) { Result r; r.pos = v.value; return r; }
Result vert(Input i) { return make(i.inner); }
float4 frag(FragAlias f) : SV_Target { return f.color; }
)");
    const PruneResult result = pruneHlsl(input, "vert");
    EXPECT_THAT(result.text, HasSubstr("struct Inner"));
    EXPECT_THAT(result.text, HasSubstr("struct Input"));
    EXPECT_THAT(result.text, HasSubstr("struct Result"));
    EXPECT_THAT(result.text, HasSubstr("typedef Inner InnerAlias;"));
    EXPECT_THAT(result.text, Not(HasSubstr("FragOnly")));
    EXPECT_THAT(result.text, Not(HasSubstr("FragAlias")));
}

TEST(StagePruner, KeepsACbufferWholeWhenAnyMemberIsReferenced) {
    const std::string input = program(R"(
#line 1 0
cbuffer PerDraw : register(b0) {
    float4x4 M;
    float4 fragOnlyTint;
}
cbuffer Lighting { float4 lightDir; float4 lightColor; };
float4 vert(float4 p : POSITION) : SV_POSITION { return mul(M, p); }
float4 frag() : SV_Target { return lightColor; }
)");
    const PruneResult result = pruneHlsl(input, "vert");
    EXPECT_EQ(result.text, program(R"(
#line 1 0
cbuffer PerDraw : register(b0) {
    float4x4 M;
    float4 fragOnlyTint;
}
#line 6 0
float4 vert(float4 p : POSITION) : SV_POSITION { return mul(M, p); }
)"));
    EXPECT_THAT(pruneHlsl(input, "frag").text, HasSubstr("cbuffer Lighting"));
}

TEST(StagePruner, KeepsStaticConstArraysAndWhatTheirInitializersName) {
    const std::string input = program(R"(
#line 1 0
static const float kBase = 0.5;
static const float3 kDirs[2] = { float3(kBase, 0, 0), float3(0, 1, 0) };
static const float kUnused[3] = { 1, 2, 3 };
static float gScratch;
float4 vert(float4 p : POSITION) : SV_POSITION { return p + kDirs[1].xyzz; }
)");
    const PruneResult result = pruneHlsl(input, "vert");
    EXPECT_THAT(result.text,
                HasSubstr("static const float kBase = 0.5;\nstatic const float3 kDirs"));
    EXPECT_THAT(result.text, Not(HasSubstr("kUnused")));
    EXPECT_THAT(result.text, Not(HasSubstr("gScratch")));
}

TEST(StagePruner, KeepsTextureSamplerPairsAndIgnoresMemberNames) {
    const std::string input = program(R"(
#line 1 0
Texture2D<float4> _HeightMap : register(t0);
SamplerState sampler_HeightMap : register(s0);
Texture2D<float4> _Albedo;
SamplerState sampler_Albedo;
static const float SampleLevel = 3;
static const float3 normal = float3(0, 1, 0);
struct VIn { float4 pos : POSITION; float3 normal : NORMAL; };
float4 vert(VIn v) : SV_POSITION {
    float h = _HeightMap.SampleLevel(sampler_HeightMap, v.pos.xy, 0).r;
    return v.pos + float4(v.normal * h, 0);
}
float4 frag(float2 uv : TEXCOORD0) : SV_Target { return _Albedo.Sample(sampler_Albedo, uv); }
)");
    const PruneResult result = pruneHlsl(input, "vert");
    EXPECT_THAT(result.text, HasSubstr("Texture2D<float4> _HeightMap : register(t0);\n"
                                       "SamplerState sampler_HeightMap : register(s0);\n"));
    EXPECT_THAT(result.text, Not(HasSubstr("_Albedo")));
    EXPECT_THAT(result.text, Not(HasSubstr("static const")));  // `.SampleLevel`, `.normal`
}

TEST(StagePruner, KeepsAllLooseUniformsTogetherBecauseTheyFormGlobalBlock) {
    // glslang packs every non-static, non-resource HLSL global into one `$Global` uniform block
    // whenever one of them is used; dropping fragment-only members would move the offsets.
    const std::string input = program(R"(
#line 1 0
float4 _Tint;
float4x4 M;
uniform float _FragOnly;
sampler2D _MainTex;
float4 vert(float4 p : POSITION) : SV_POSITION { return mul(M, p); }
float4 vertNoGlobals(float4 p : POSITION) : SV_POSITION { return p; }
float4 frag(float2 uv : TEXCOORD0) : SV_Target { return tex2D(_MainTex, uv) * _Tint; }
)");
    EXPECT_THAT(pruneHlsl(input, "vert").text,
                HasSubstr("float4 _Tint;\nfloat4x4 M;\nuniform float _FragOnly;\n#line 5 0"));
    EXPECT_EQ(pruneHlsl(input, "vertNoGlobals").text,
              "#line 6 0\nfloat4 vertNoGlobals(float4 p : POSITION) : SV_POSITION { return p; }\n");
}

TEST(StagePruner, KeepsComputeAttributesGroupSharedAndSemantics) {
    const std::string input = program(R"(
#line 1 0
groupshared float gTile[64];
groupshared float gUnused[64];
RWStructuredBuffer<float> gOut : register(u0);
[numthreads(8, 8, 1)]
void cs(uint3 id : SV_DispatchThreadID) {
    gTile[id.x] = id.y;
    [unroll] for (int k = 0; k < 2; ++k) { gOut[id.x + k] = gTile[k]; }
}
)");
    const PruneResult result = pruneToEntryPoint(input, "cs", ShaderDialect::Hlsl);
    EXPECT_THAT(result.text, HasSubstr("[numthreads(8, 8, 1)]\nvoid cs("));
    EXPECT_THAT(result.text, HasSubstr("groupshared float gTile[64];"));
    EXPECT_THAT(result.text, HasSubstr("RWStructuredBuffer<float> gOut"));
    EXPECT_THAT(result.text, Not(HasSubstr("gUnused")));
}

TEST(StagePruner, GlslMainKeepsInterfaceBlocksGlobalsAndDirectives) {
    // glslang emits every GLSL global variable and block even when unused, so only functions,
    // struct types and `const` globals are pruned.
    const std::string input = program(R"(
#version 450
#extension GL_GOOGLE_include_directive : enable
#line 1 0
precision highp float;
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 0) out vec3 vNormal;
struct Light { vec4 color; vec4 dir; };
struct FragOnly { float x; };
layout(std140, set = 0, binding = 0) uniform PerFrame { mat4 viewProj; Light mainLight; } frame;
layout(std140, set = 0, binding = 1) uniform PerObject { mat4 model; };
const float kScale = 2.0;
const float kFragOnly = 0.5;
vec3 transformNormal(vec3 n) { return mat3(model) * n; }
float fragHelper(FragOnly f) { return f.x * kFragOnly; }
void main() {
    gl_Position = frame.viewProj * model * vec4(aPosition * kScale, 1.0);
    vNormal = transformNormal(aNormal);
}
)");
    const PruneResult result = pruneToEntryPoint(input, "main", ShaderDialect::Glsl);
    ASSERT_TRUE(result.pruned);
    EXPECT_THAT(result.keptFunctions, ElementsAre("transformNormal", "main"));
    EXPECT_EQ(result.text, program(R"(
#version 450
#extension GL_GOOGLE_include_directive : enable
#line 1 0
precision highp float;
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 0) out vec3 vNormal;
struct Light { vec4 color; vec4 dir; };
#line 7 0
layout(std140, set = 0, binding = 0) uniform PerFrame { mat4 viewProj; Light mainLight; } frame;
layout(std140, set = 0, binding = 1) uniform PerObject { mat4 model; };
const float kScale = 2.0;
#line 11 0
vec3 transformNormal(vec3 n) { return mat3(model) * n; }
#line 13 0
void main() {
    gl_Position = frame.viewProj * model * vec4(aPosition * kScale, 1.0);
    vNormal = transformNormal(aNormal);
}
)"));
    expectLinesMapToOrigin(input, result.text);
}

// glslang's preprocessed output for a Unity forward-lighting pass: a line tagged `P|`, `D|` or
// `V|` exists only with POINT, DIRECTIONAL or VERTEXLIGHT_ON, and is blank otherwise (as the
// preprocessor leaves it), so every variant keeps the same line numbers.
const std::string_view kForwardLightingTemplate = R"(#line 1 0
#pragma target 3.0
#pragma vertex vert
#pragma fragment frag
#line 1 1
float4x4 unity_ObjectToWorld;
float4x4 unity_WorldToObject;
float4x4 unity_MatrixVP;
float3 _WorldSpaceCameraPos;
float4 _WorldSpaceLightPos0;
float4 _LightColor0;
float4 unity_4LightPosX0;
float4 unity_4LightPosY0;
float4 unity_4LightPosZ0;
float4 unity_4LightAtten0;
float4 unity_LightColor[8];
float3 UnityObjectToWorldNormal(float3 n) {
    return normalize(mul(n, (float3x3)unity_WorldToObject));
}
float3 Shade4PointLights(float3 pos, float3 normal) {
    float4 toX = unity_4LightPosX0 - pos.x;
    float4 toY = unity_4LightPosY0 - pos.y;
    float4 toZ = unity_4LightPosZ0 - pos.z;
    float4 lenSq = max(toX * toX + toY * toY + toZ * toZ, 1e-6);
    float4 ndotl = max(0, (toX * normal.x + toY * normal.y + toZ * normal.z) * rsqrt(lenSq));
    float4 diff = ndotl / (1.0 + lenSq * unity_4LightAtten0);
    return unity_LightColor[0].rgb * diff.x + unity_LightColor[1].rgb * diff.y +
           unity_LightColor[2].rgb * diff.z + unity_LightColor[3].rgb * diff.w;
}
#line 12 0
sampler2D _MainTex;
float4 _MainTex_ST;
float4 _Tint;
float _Smoothness;
P|sampler2D _LightTexture0;
static const float kPi = 3.14159265;

struct VertexData {
    float4 position : POSITION;
    float3 normal : NORMAL;
    float2 uv : TEXCOORD0;
};

struct Interpolators {
    float4 position : SV_POSITION;
    float2 uv : TEXCOORD0;
    float3 normal : TEXCOORD1;
    float3 worldPos : TEXCOORD2;
V|    float3 vertexLightColor : TEXCOORD3;
};

struct LightSample { float3 color; float3 dir; };

void ComputeVertexLightColor(inout Interpolators i) {
V|    i.vertexLightColor = Shade4PointLights(i.worldPos, i.normal);
}

Interpolators vert(VertexData v) {
    Interpolators i;
    i.worldPos = mul(unity_ObjectToWorld, v.position).xyz;
    i.position = mul(unity_MatrixVP, float4(i.worldPos, 1));
    i.normal = UnityObjectToWorldNormal(v.normal);
    i.uv = v.uv * _MainTex_ST.xy + _MainTex_ST.zw;
    ComputeVertexLightColor(i);
    return i;
}

LightSample CreateLight(Interpolators i) {
    LightSample light;
P|    float3 toLight = _WorldSpaceLightPos0.xyz - i.worldPos;
P|    light.dir = normalize(toLight);
P|    float atten = tex2D(_LightTexture0, dot(toLight, toLight).rr).r;
D|    light.dir = _WorldSpaceLightPos0.xyz;
D|    float atten = 1;
    light.color = _LightColor0.rgb * atten;
    return light;
}

float3 IndirectDiffuse(Interpolators i) {
    float3 diffuse = 0;
V|    diffuse = i.vertexLightColor;
    return diffuse;
}

float3 BlinnPhong(float3 albedo, float3 normal, float3 viewDir, LightSample light) {
    float3 halfDir = normalize(light.dir + viewDir);
    float ndotl = saturate(dot(normal, light.dir));
    float spec = pow(saturate(dot(normal, halfDir)), exp2(10 * _Smoothness + 1));
    return (albedo / kPi * ndotl + spec) * light.color;
}

float4 frag(Interpolators i) : SV_Target {
    i.normal = normalize(i.normal);
    float3 viewDir = normalize(_WorldSpaceCameraPos - i.worldPos);
    float3 albedo = tex2D(_MainTex, i.uv).rgb * _Tint.rgb;
    float3 color = BlinnPhong(albedo, i.normal, viewDir, CreateLight(i));
    return float4(color + albedo * IndirectDiffuse(i), 1);
}
)";

std::string forwardLighting(bool pointLight, bool vertexLight) {
    std::string out;
    for (const std::string& line : splitLines(kForwardLightingTemplate)) {
        const bool tagged = line.size() > 1 && line[1] == '|';
        const bool active = !tagged || (line[0] == 'P' && pointLight) ||
                            (line[0] == 'D' && !pointLight) || (line[0] == 'V' && vertexLight);
        out += active ? (tagged ? line.substr(2) : line) : std::string();
        out += '\n';
    }
    return out;
}

TEST(StagePruner, ForwardLightingVertexKeepsWhatTheVertexProgramReaches) {
    const std::string input = forwardLighting(/*pointLight=*/true, /*vertexLight=*/true);
    const PruneResult result = pruneHlsl(input, "vert");
    ASSERT_TRUE(result.pruned);
    EXPECT_THAT(result.keptFunctions, ElementsAre("UnityObjectToWorldNormal", "Shade4PointLights",
                                                  "ComputeVertexLightColor", "vert"));
    EXPECT_THAT(result.text, HasSubstr("#pragma vertex vert"));
    EXPECT_THAT(result.text, HasSubstr("float _Smoothness;"));  // $Global member
    EXPECT_THAT(result.text, HasSubstr("struct VertexData"));
    for (const char* fragmentOnly : {"sampler2D", "kPi", "LightSample", "BlinnPhong", "frag("}) {
        EXPECT_THAT(result.text, Not(HasSubstr(fragmentOnly)));
    }
    expectLinesMapToOrigin(input, result.text);
}

TEST(StagePruner, ForwardLightingFragmentKeepsLightBrdfAndTextures) {
    const std::string input = forwardLighting(/*pointLight=*/true, /*vertexLight=*/false);
    const PruneResult result = pruneHlsl(input, "frag");
    ASSERT_TRUE(result.pruned);
    EXPECT_THAT(result.keptFunctions,
                ElementsAre("CreateLight", "IndirectDiffuse", "BlinnPhong", "frag"));
    EXPECT_THAT(result.text, HasSubstr("sampler2D _MainTex;"));
    EXPECT_THAT(result.text, HasSubstr("sampler2D _LightTexture0;"));
    EXPECT_THAT(result.text, HasSubstr("static const float kPi"));
    EXPECT_THAT(result.text, Not(HasSubstr("VertexData")));
    expectLinesMapToOrigin(input, result.text);
}

TEST(StagePruner, VariantsDifferingOnlyInFragmentCodeGiveIdenticalVertexText) {
    std::set<std::string> vertexTexts;
    std::set<std::string> fragmentTexts;
    for (const bool pointLight : {false, true}) {
        for (const bool vertexLight : {false, true}) {
            const std::string input = forwardLighting(pointLight, vertexLight);
            vertexTexts.insert(pruneHlsl(input, "vert").text);
            fragmentTexts.insert(pruneHlsl(input, "frag").text);
        }
    }
    EXPECT_EQ(vertexTexts.size(), 2u);  // only VERTEXLIGHT_ON matters to the vertex stage
    EXPECT_EQ(fragmentTexts.size(), 4u);
    EXPECT_EQ(pruneHlsl(forwardLighting(false, false), "vert").text,
              pruneHlsl(forwardLighting(true, false), "vert").text);
}

TEST(StagePruner, VariantOnlyLooseUniformStillChangesTheVertexText) {
    // A uniform declared under `#ifdef POINT` changes `$Global`, hence the vertex SPIR-V too.
    std::string withUniform = forwardLighting(true, false);
    withUniform.replace(withUniform.find("sampler2D _LightTexture0;"), 25,
                        "float4x4 _WorldToLight;");
    EXPECT_NE(pruneHlsl(withUniform, "vert").text,
              pruneHlsl(forwardLighting(true, false), "vert").text);
}

TEST(StagePruner, KeepsTheLineDirectiveFormAndRestatesANamedSourceString) {
    const std::string sourceless = "#line 20\nstatic float a;\n\nfloat4 vert() { return 0; }\n";
    EXPECT_EQ(pruneHlsl(sourceless, "vert").text, "#line 22\nfloat4 vert() { return 0; }\n");
    const std::string input = program(R"(
#line 1 3
float4x4 M;
#line 40
static float unused;
float4 vert(float4 p : POSITION) : SV_POSITION { return mul(M, p); }
)");
    const PruneResult result = pruneHlsl(input, "vert");
    EXPECT_EQ(result.text,
              "#line 1 3\nfloat4x4 M;\n#line 41 3\n"
              "float4 vert(float4 p : POSITION) : SV_POSITION { return mul(M, p); }\n");
    expectLinesMapToOrigin(input, result.text);
}

TEST(StagePruner, PadsLinesBeforeTheFirstLineDirectiveToTheirPhysicalLine) {
    const std::string input =
        "static float a;\nstatic float b;\n\nfloat4 vert() : SV_POSITION\n"
        "{ return b; }\n#line 1 1\nfloat4 frag() : SV_Target { return a; }\n";
    const PruneResult result = pruneHlsl(input, "vert");
    EXPECT_EQ(result.text, "\nstatic float b;\n\nfloat4 vert() : SV_POSITION\n{ return b; }\n");
    expectLinesMapToOrigin(input, result.text);
}

TEST(StagePruner, KeepsOnlyTheKeptPiecesOfASharedLine) {
    const std::string input =
        "#line 1 0\nstatic float a = 1; static float b = 2;\n"
        "float4 vert() : SV_POSITION { return b; } float4 frag() : SV_Target { return a; }\n";
    const PruneResult result = pruneHlsl(input, "vert");
    EXPECT_EQ(result.text,
              "#line 1 0\nstatic float b = 2;\n"
              "float4 vert() : SV_POSITION { return b; }\n");
    expectLinesMapToOrigin(input, result.text);
}

TEST(StagePruner, PruningIsIdempotent) {
    for (const char* entry : {"vert", "frag"}) {
        const std::string once = pruneHlsl(forwardLighting(true, true), entry).text;
        EXPECT_EQ(pruneHlsl(once, entry).text, once) << entry;
    }
}

TEST(StagePruner, IgnoresCommentsAndKeepsLinesThatFollowThem) {
    const std::string input =
        "#line 1 0\n/* a block\n   comment */ float4x4 M; // trailing\n"
        "float4 vert(float4 p : POSITION) : SV_POSITION { return mul(M, p); }\n";
    const PruneResult result = pruneHlsl(input, "vert");
    EXPECT_EQ(result.text,
              "#line 2 0\nfloat4x4 M;\n"
              "float4 vert(float4 p : POSITION) : SV_POSITION { return mul(M, p); }\n");
}

void expectFallBack(std::string_view input, std::string_view entry) {
    const PruneResult result = pruneHlsl(input, entry);
    EXPECT_FALSE(result.pruned) << input;
    EXPECT_EQ(result.text, input);
    EXPECT_TRUE(result.keptFunctions.empty());
}

TEST(StagePruner, FallsBackWhenTheEntryPointIsMissingOrOnlyDeclared) {
    expectFallBack(kTwoStages, "main");
    expectFallBack("float4 vert(float4 p : POSITION) : SV_POSITION;\n", "vert");
    expectFallBack("static float vert;\n", "vert");
}

TEST(StagePruner, FallsBackOnInputItCannotParse) {
    expectFallBack("float4 vert() : SV_POSITION { return 0;\n", "vert");             // open brace
    expectFallBack("float4 vert() : SV_POSITION { return 0; }}\n", "vert");          // extra brace
    expectFallBack("float4 vert() : SV_POSITION { return (0]; }\n", "vert");         // mismatch
    expectFallBack("float4 vert() : SV_POSITION { return 0; }\nfloat x\n", "vert");  // no `;`
    expectFallBack("/* open\nfloat4 vert() : SV_POSITION { return 0; }\n", "vert");
    expectFallBack("#line x\nfloat4 vert() : SV_POSITION { return 0; }\n", "vert");
}

}  // namespace
}  // namespace varc::frontend
