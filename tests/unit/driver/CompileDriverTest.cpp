// SPDX-License-Identifier: Apache-2.0
// The compile driver: distinct programs per stage, dedup before and after glslang, determinism
// across thread counts, grouped and mapped errors.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <set>
#include <string_view>

#include "varc/cache/CacheSpec.h"
#include "varc/driver/CompileDriver.h"
#include "varc/frontend/ShaderLoader.h"
#include "varc/includes/FileSystem.h"
#include "varc/variants/PassKeywords.h"

namespace varc::driver {
namespace {

// Two keywords, each tested by one stage only: 4 variants, 2 vertex + 2 fragment programs.
constexpr const char* kTwoKeywordShader = R"(Shader "Test/TwoKeywords" {
    SubShader {
        Pass {
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile _ WOBBLE
            #pragma multi_compile _ TINTED
            #include "Common.cginc"
            float4 _Tint;
            float4 vert(float4 p : POSITION) : SV_POSITION {
            #ifdef WOBBLE
                p.x += sin(p.y);
            #endif
                return p * scale();
            }
            float4 frag() : SV_Target {
            #ifdef TINTED
                return _Tint;
            #else
                return float4(1, 1, 1, 1);
            #endif
            }
            ENDCG
        }
    }
}
)";

constexpr const char* kCommon = R"(#ifndef COMMON_INCLUDED
#define COMMON_INCLUDED
float scale() { return 2.0; }
#endif
)";

// Whether |spirv| holds an instruction with |opcode| (OpName = 5, OpMemberName = 6).
bool hasInstruction(const std::vector<uint32_t>& spirv, uint32_t opcode) {
    for (size_t i = 5; i < spirv.size(); i += std::max<uint32_t>(spirv[i] >> 16, 1)) {
        if ((spirv[i] & 0xffff) == opcode) return true;
    }
    return false;
}

// |text| with its first |from| replaced by |to| (|from| must occur).
std::string replaced(std::string text, std::string_view from, std::string_view to) {
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "'" << from << "' not in the shader";
    if (at != std::string::npos) text.replace(at, from.size(), to);
    return text;
}

class CompileDriverTest : public ::testing::Test {
protected:
    std::optional<BuildOutput> build(const std::string& shaderText, BuildOptions options = {}) {
        mFileSystem.add("shaders/test.shader", shaderText).add("shaders/Common.cginc", kCommon);
        auto shader =
            frontend::loadShader("shaders/test.shader", mFileSystem, mSourceMap, {}, mDiagnostics);
        if (!shader) return std::nullopt;
        mShaders.clear();
        mShaders.push_back(std::move(*shader));
        return buildPrograms(mShaders, mSourceMap, options, mDiagnostics);
    }

    // The first diagnostic's message, for assertion output; "" when there is none.
    std::string firstMessage() const {
        return mDiagnostics.diagnostics().empty() ? "" : mDiagnostics.diagnostics()[0].message;
    }

    includes::InMemoryFileSystem mFileSystem;
    includes::SourceMap mSourceMap;
    DiagnosticList mDiagnostics;
    std::vector<frontend::LoadedShader> mShaders;
};

TEST_F(CompileDriverTest, KeywordsTouchingOneStageEachGiveTwoProgramsPerStage) {
    auto output = build(kTwoKeywordShader);
    ASSERT_TRUE(output) << firstMessage();
    ASSERT_EQ(output->passes.size(), 1u);
    const CompiledPass& pass = output->passes[0];
    EXPECT_EQ(pass.variants.size(), 4u);
    EXPECT_EQ(pass.stats.distinctSources[stageIndex(Stage::Vertex)], 2u);
    EXPECT_EQ(pass.stats.distinctSources[stageIndex(Stage::Fragment)], 2u);
    EXPECT_EQ(pass.stats.distinctModules[stageIndex(Stage::Vertex)], 2u);
    EXPECT_EQ(pass.stats.distinctModules[stageIndex(Stage::Fragment)], 2u);
    EXPECT_EQ(output->compiledSources, 4u);
    EXPECT_EQ(output->programs.size(), 4u);
    ASSERT_EQ(pass.setStageEffects.size(), 2u);
    EXPECT_EQ(pass.setStageEffects[0], stageBit(Stage::Vertex));
    EXPECT_EQ(pass.setStageEffects[1], stageBit(Stage::Fragment));
}

TEST_F(CompileDriverTest, KeptPrunedSourcesFollowTheKeywordsEachStageSees) {
    BuildOptions options;
    options.keepPrunedSources = true;
    auto output = build(kTwoKeywordShader, options);
    ASSERT_TRUE(output) << firstMessage();
    const CompiledPass& pass = output->passes[0];
    ASSERT_EQ(pass.variantSources.size(), pass.variants.size());
    EXPECT_EQ(output->prunedSources.size(), output->compiledSources);
    // Enumeration order: {}, {TINTED}, {WOBBLE}, {TINTED WOBBLE} (the first set varies slowest).
    auto source = [&](size_t variant, Stage stage) {
        return pass.variantSources[variant][stageIndex(stage)];
    };
    EXPECT_EQ(source(0, Stage::Vertex), source(1, Stage::Vertex));  // TINTED: fragment only
    EXPECT_NE(source(0, Stage::Fragment), source(1, Stage::Fragment));
    EXPECT_NE(source(0, Stage::Vertex), source(2, Stage::Vertex));  // WOBBLE: vertex only
    EXPECT_EQ(source(0, Stage::Fragment), source(2, Stage::Fragment));
    EXPECT_EQ(source(0, Stage::Geometry), kNoProgram);
    const std::string& wobbling = output->prunedSources[source(2, Stage::Vertex)];
    EXPECT_NE(wobbling.find("sin"), std::string::npos);
    EXPECT_EQ(output->prunedSources[source(0, Stage::Vertex)].find("sin"), std::string::npos);
}

TEST_F(CompileDriverTest, PrunedSourcesAreNotKeptUnlessAsked) {
    auto output = build(kTwoKeywordShader);
    ASSERT_TRUE(output) << firstMessage();
    EXPECT_TRUE(output->prunedSources.empty());
    EXPECT_TRUE(output->passes[0].variantSources.empty());
}

TEST_F(CompileDriverTest, WithoutPruningEveryVariantTextIsDistinctButModulesStillDedup) {
    BuildOptions options;
    options.pruneStages = false;
    auto output = build(kTwoKeywordShader, options);
    ASSERT_TRUE(output);
    const CompiledPass& pass = output->passes[0];
    EXPECT_EQ(pass.stats.distinctSources[stageIndex(Stage::Vertex)], 4u);
    EXPECT_EQ(pass.stats.distinctModules[stageIndex(Stage::Vertex)], 2u);
    EXPECT_EQ(pass.stats.distinctModules[stageIndex(Stage::Fragment)], 2u);
}

TEST_F(CompileDriverTest, OutputIsIdenticalForAnyThreadCount) {
    BuildOptions one;
    one.jobs = 1;
    auto first = build(kTwoKeywordShader, one);
    BuildOptions four;
    four.jobs = 4;
    auto second = build(kTwoKeywordShader, four);
    ASSERT_TRUE(first && second);
    ASSERT_EQ(first->programs.size(), second->programs.size());
    for (size_t i = 0; i < first->programs.size(); ++i) {
        EXPECT_EQ(first->programs[i].spirv, second->programs[i].spirv) << i;
    }
    for (size_t v = 0; v < first->passes[0].variants.size(); ++v) {
        EXPECT_EQ(first->passes[0].variants[v].programs, second->passes[0].variants[v].programs);
    }
}

// A one-parameter macro called with an empty argument stops glslang; the pass's text is
// expanded once for all its variants, before any is preprocessed (TextRewriteMemo), and the
// programs are the same whichever thread preprocesses first.
TEST_F(CompileDriverTest, EmptyMacroArgumentsExpandOnceWithTheSameProgramsOnAnyThreadCount) {
    std::string shader = replaced(kTwoKeywordShader, "                return _Tint;",
                                  "                return TINT_OF();");
    shader = replaced(shader, "float4 _Tint;", "float4 _Tint;\n#define TINT_OF(x) _Tint x");
    BuildOptions one;
    one.jobs = 1;
    auto first = build(shader, one);
    ASSERT_TRUE(first) << firstMessage();
    BuildOptions three;
    three.jobs = 3;
    auto second = build(shader, three);
    ASSERT_TRUE(second) << firstMessage();
    // As without the macro: 2 vertex and 2 fragment programs, the TINTED ones reading _Tint.
    EXPECT_EQ(first->compiledSources, 4u);
    ASSERT_EQ(first->programs.size(), second->programs.size());
    for (size_t i = 0; i < first->programs.size(); ++i) {
        EXPECT_EQ(first->programs[i].spirv, second->programs[i].spirv) << i;
    }
    auto plain = build(kTwoKeywordShader, one);
    ASSERT_TRUE(plain);
    ASSERT_EQ(plain->programs.size(), first->programs.size());
    for (size_t i = 0; i < plain->programs.size(); ++i) {
        EXPECT_EQ(plain->programs[i].spirv, first->programs[i].spirv) << i;
    }
}

TEST_F(CompileDriverTest, ReflectsSemanticsAndUniforms) {
    auto output = build(kTwoKeywordShader);
    ASSERT_TRUE(output);
    const pack::PackVariant& tinted = output->passes[0].variants[1];  // [TINTED]
    const auto& vertex = output->programs[tinted.programs[stageIndex(Stage::Vertex)]];
    ASSERT_EQ(vertex.reflection.vertexInputs.size(), 1u);
    EXPECT_EQ(vertex.reflection.vertexInputs[0].semantic, "POSITION");
    EXPECT_EQ(vertex.reflection.vertexInputs[0].type, "float4");
    const auto& fragment = output->programs[tinted.programs[stageIndex(Stage::Fragment)]];
    ASSERT_EQ(fragment.reflection.uniformBlocks.size(), 1u);
    ASSERT_EQ(fragment.reflection.uniformBlocks[0].members.size(), 1u);
    EXPECT_EQ(fragment.reflection.uniformBlocks[0].members[0].name, "_Tint");
    EXPECT_EQ(fragment.reflection.uniformBlocks[0].members[0].type, "float4");
}

// SHADER_ABI.md §1: each stage's descriptors live in their own set (vertex 0, fragment 1), and
// the reflection reports every resource's real set and binding.
TEST_F(CompileDriverTest, ReflectsOneDescriptorSetPerStageWithRealBindings) {
    auto output = build(R"(Shader "Test/Textured" {
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            float4x4 _Transform;
            sampler2D _MainTex;
            sampler2D _DetailTex;
            float4 vert(float4 p : POSITION) : SV_POSITION { return mul(_Transform, p); }
            float4 frag(float4 p : SV_POSITION) : SV_Target {
                return tex2D(_MainTex, p.xy) * tex2D(_DetailTex, p.yx);
            }
            ENDCG
        }
    }
}
)");
    ASSERT_TRUE(output);
    const pack::PackVariant& variant = output->passes[0].variants[0];
    const auto& vertex = output->programs[variant.programs[stageIndex(Stage::Vertex)]].reflection;
    const auto& fragment =
        output->programs[variant.programs[stageIndex(Stage::Fragment)]].reflection;
    ASSERT_EQ(vertex.uniformBlocks.size(), 1u);
    EXPECT_EQ(vertex.uniformBlocks[0].set, 0u);
    ASSERT_EQ(fragment.resources.size(), 2u);
    std::set<uint32_t> bindings;
    for (const pack::ResourceBinding& resource : fragment.resources) {
        EXPECT_EQ(resource.set, 1u) << resource.name;
        EXPECT_EQ(resource.kind, pack::ResourceKind::CombinedImageSampler) << resource.name;
        bindings.insert(resource.binding);
    }
    EXPECT_EQ(bindings.size(), 2u) << "two textures share a binding";
}

// Builds kTwoKeywordShader including Outer.cginc (which includes Inner.cginc, where
// undefinedValue is) and returns the first error.
std::optional<Diagnostic> firstErrorThroughNestedIncludes(const std::string& outer,
                                                          includes::InMemoryFileSystem& files,
                                                          includes::SourceMap& sourceMap,
                                                          DiagnosticList& diagnostics) {
    files.add("shaders/test.shader",
              replaced(kTwoKeywordShader, "#include \"Common.cginc\"", "#include \"Outer.cginc\""));
    files.add("shaders/Outer.cginc", outer);
    files.add("shaders/Inner.cginc", "float scale() { return undefinedValue; }\n");
    auto loaded = frontend::loadShader("shaders/test.shader", files, sourceMap, {}, diagnostics);
    if (!loaded) return std::nullopt;
    std::vector<frontend::LoadedShader> shaders;
    shaders.push_back(std::move(*loaded));
    if (buildPrograms(shaders, sourceMap, {}, diagnostics)) return std::nullopt;
    for (const Diagnostic& d : diagnostics.diagnostics()) {
        if (d.severity == Severity::Error) return d;
    }
    return std::nullopt;
}

TEST_F(CompileDriverTest, ACompileErrorInANestedIncludeNotesTheIncludeChain) {
    auto error = firstErrorThroughNestedIncludes("// outer\n#include \"Inner.cginc\"\n",
                                                 mFileSystem, mSourceMap, mDiagnostics);
    ASSERT_TRUE(error) << firstMessage();
    EXPECT_EQ(mSourceMap.path(error->location.file), "shaders/Inner.cginc");
    ASSERT_EQ(error->notes.size(), 3u);
    EXPECT_EQ(mSourceMap.format(error->notes[0].location), "shaders/Outer.cginc:2");
    EXPECT_EQ(error->notes[0].message, "in file included from here");
    EXPECT_EQ(mSourceMap.format(error->notes[1].location), "shaders/test.shader:10");
    EXPECT_EQ(error->notes[1].message, "in file included from here");
    EXPECT_NE(error->notes[2].message.find("stage of pass 0"), std::string::npos);
}

TEST_F(CompileDriverTest, AnIncludeChainTheTextCannotShowStopsRatherThanGuess) {
    // Outer.cginc has no line of its own before its #include, so no #line marks it: the chain
    // must not claim test.shader included Inner.cginc.
    auto error = firstErrorThroughNestedIncludes("#include \"Inner.cginc\"\n", mFileSystem,
                                                 mSourceMap, mDiagnostics);
    ASSERT_TRUE(error) << firstMessage();
    ASSERT_EQ(error->notes.size(), 1u);
    EXPECT_NE(error->notes[0].message.find("stage of pass 0"), std::string::npos);
}

TEST_F(CompileDriverTest, ErrorInSharedIncludeIsReportedOnceWithVariantCountAndMappedLine) {
    mFileSystem.add("shaders/Common.cginc", "float scale() { return undefinedValue; }\n");
    std::string shader =
        replaced(kTwoKeywordShader, "#include \"Common.cginc\"", "#include \"Broken.cginc\"");
    mFileSystem.add("shaders/Broken.cginc", "float scale() { return undefinedValue; }\n");
    mFileSystem.add("shaders/test.shader", shader);
    auto loaded =
        frontend::loadShader("shaders/test.shader", mFileSystem, mSourceMap, {}, mDiagnostics);
    ASSERT_TRUE(loaded);
    mShaders.push_back(std::move(*loaded));
    BuildOptions options;
    options.keepGoing = true;
    EXPECT_FALSE(buildPrograms(mShaders, mSourceMap, options, mDiagnostics));
    std::vector<Diagnostic> errors;
    for (const Diagnostic& d : mDiagnostics.diagnostics()) {
        if (d.severity == Severity::Error) errors.push_back(d);
    }
    ASSERT_FALSE(errors.empty());
    EXPECT_EQ(mSourceMap.path(errors[0].location.file), "shaders/Broken.cginc");
    EXPECT_EQ(errors[0].location.line, 1u);
    EXPECT_NE(errors[0].message.find("undefinedValue"), std::string::npos) << errors[0].message;
    size_t mentions = 0;
    for (const Diagnostic& d : errors)
        mentions += d.message.find("undefinedValue") != std::string::npos;
    EXPECT_EQ(mentions, 1u);
    ASSERT_FALSE(errors[0].notes.empty());
    // Both stages of all 4 variants include it: 4 variants, not 8 programs.
    EXPECT_NE(errors[0].notes.back().message.find("; 4 variants affected"), std::string::npos)
        << errors[0].notes.back().message;
    EXPECT_NE(errors[0].notes.back().message.find("stage of pass 0"), std::string::npos);
}

TEST_F(CompileDriverTest, VariantsDifferingOnlyInUnobservedDefinesSharePreprocessing) {
    std::string shader =
        replaced(kTwoKeywordShader, "#pragma multi_compile _ TINTED",
                 "#pragma multi_compile _ TINTED\n#pragma multi_compile _ NEVER_TESTED");
    auto output = build(shader);
    ASSERT_TRUE(output);
    const CompiledPass& pass = output->passes[0];
    EXPECT_EQ(pass.variants.size(), 8u);
    // 8 variants x 2 stages, but neither NEVER_TESTED nor the SHADER_STAGE_* macros occur in the
    // text, and each stage's entry point reaches only its own keyword: one preprocessing with
    // neither, one with WOBBLE (the vertex stage's), one with TINTED (the fragment stage's).
    EXPECT_EQ(output->preprocessedPrograms, 3u);
    EXPECT_EQ(pass.stats.distinctSources[stageIndex(Stage::Vertex)], 2u);
    EXPECT_EQ(pass.stats.distinctSources[stageIndex(Stage::Fragment)], 2u);
    EXPECT_EQ(output->compiledSources, 4u);
}

TEST_F(CompileDriverTest, AStageMacroTheTextTestsIsPreprocessedPerStage) {
    std::string shader =
        replaced(kTwoKeywordShader, "float4 _Tint;",
                 "#ifdef SHADER_STAGE_VERTEX\nfloat4 _VertexOnly;\n#endif\nfloat4 _Tint;");
    auto output = build(shader);
    ASSERT_TRUE(output);
    // Per stage, since their preambles differ: 2 WOBBLE choices for the vertex stage, 2 TINTED
    // choices for the fragment stage.
    EXPECT_EQ(output->preprocessedPrograms, 4u);
}

TEST_F(CompileDriverTest, APreprocessingErrorSharedByVariantsIsReportedOnce) {
    std::string shader =
        replaced(kTwoKeywordShader, "float4 _Tint;",
                 "#ifdef TINTED\n#error tinted is unsupported\n#endif\nfloat4 _Tint;");
    BuildOptions options;
    options.keepGoing = true;
    EXPECT_FALSE(build(shader, options));
    size_t mentions = 0;
    for (const Diagnostic& d : mDiagnostics.diagnostics()) {
        if (d.severity != Severity::Error) continue;
        ASSERT_FALSE(d.notes.empty());
        EXPECT_NE(d.notes.back().message.find("TINTED"), std::string::npos)
            << d.notes.back().message;
        if (d.message.find("tinted is unsupported") == std::string::npos) continue;
        ++mentions;
        // The 2 TINTED variants, each met through both stages, count once.
        EXPECT_NE(d.notes.back().message.find("; 2 variants affected"), std::string::npos)
            << d.notes.back().message;
        EXPECT_EQ(mSourceMap.path(d.location.file), "shaders/test.shader");
    }
    EXPECT_EQ(mentions, 1u);
}

TEST_F(CompileDriverTest, ASecondBuildTakesEveryProgramFromTheCacheWithIdenticalResults) {
    BuildOptions options;
    const std::string cacheDirectory =
        ::testing::TempDir() + "varc-driver-cache-" + std::to_string(::getpid());
    std::filesystem::remove_all(cacheDirectory);
    options.cache = std::make_shared<cache::CacheChain>(
        cache::CacheChain::open({cache::directoryCacheSpec(cacheDirectory)}));
    auto cold = build(kTwoKeywordShader, options);
    ASSERT_TRUE(cold);
    EXPECT_EQ(cold->cachedSources, 0u);
    auto warm = build(kTwoKeywordShader, options);
    ASSERT_TRUE(warm);
    EXPECT_EQ(warm->cachedSources, warm->compiledSources);
    EXPECT_EQ(warm->preprocessedPrograms, 0u) << "every pruned source comes from the cache";
    // One per distinct (preprocessing, stage): the 3 preprocessings (neither keyword, WOBBLE,
    // TINTED) each serve both stages.
    EXPECT_EQ(warm->cachedStageSources, 6u);
    ASSERT_EQ(warm->programs.size(), cold->programs.size());
    for (size_t i = 0; i < cold->programs.size(); ++i) {
        EXPECT_EQ(warm->programs[i].spirv, cold->programs[i].spirv) << i;
        EXPECT_EQ(warm->programs[i].reflection, cold->programs[i].reflection) << i;
    }
    // -g reads the same entries and ships the named form.
    options.debugNames = true;
    auto named = build(kTwoKeywordShader, options);
    ASSERT_TRUE(named);
    EXPECT_EQ(named->cachedSources, named->compiledSources);
    for (const pack::PackProgram& program : named->programs) {
        EXPECT_TRUE(hasInstruction(program.spirv, 5)) << "OpName expected with debug names";
    }
    options.debugNames = false;
    // A different optimisation level is a different program: nothing comes from the cache.
    options.optimization = OptimizationLevel::None;
    auto other = build(kTwoKeywordShader, options);
    ASSERT_TRUE(other);
    EXPECT_EQ(other->cachedSources, 0u);
    std::filesystem::remove_all(cacheDirectory);
}

TEST_F(CompileDriverTest, ShippedSpirvHasNoNamesUnlessAskedButReflectionKeepsThem) {
    for (bool debugNames : {false, true}) {
        BuildOptions options;
        options.debugNames = debugNames;
        auto output = build(kTwoKeywordShader, options);
        ASSERT_TRUE(output);
        bool sawTint = false;
        for (const pack::PackProgram& program : output->programs) {
            EXPECT_EQ(hasInstruction(program.spirv, 5), debugNames);
            for (const pack::UniformBlock& block : program.reflection.uniformBlocks) {
                for (const pack::BlockMember& member : block.members)
                    sawTint |= member.name == "_Tint";
            }
        }
        EXPECT_TRUE(sawTint) << "reflection must name the members either way";
    }
}

TEST_F(CompileDriverTest, MissingEntryPragmaIsAnError) {
    std::string shader = replaced(kTwoKeywordShader, "#pragma fragment frag", "");
    EXPECT_FALSE(build(shader));
    ASSERT_TRUE(mDiagnostics.hasErrors());
    EXPECT_NE(mDiagnostics.diagnostics()[0].message.find("missing #pragma fragment"),
              std::string::npos);
}

// Unity's compilers accept a shader that defines its own pass macro (a warning there); glslang
// would stop at "Macro redefined", so varc's own definition takes the text's replacement.
TEST_F(CompileDriverTest, AShaderDefiningItsOwnPassMacroBuilds) {
    std::string shader = replaced(kTwoKeywordShader, "#include \"Common.cginc\"",
                                  "#define UNITY_PASS_FORWARDBASE\n#include \"Common.cginc\"");
    auto output = build(shader);
    ASSERT_TRUE(output) << firstMessage();
    EXPECT_FALSE(mDiagnostics.hasErrors());
}

// glslang parses GetRenderTargetSampleCount() and then crashes generating SPIR-V for it.
TEST_F(CompileDriverTest, GetRenderTargetSampleCountIsOneSample) {
    std::string shader = replaced(kTwoKeywordShader, "return float4(1, 1, 1, 1);",
                                  "return float4(1, 1, 1, GetRenderTargetSampleCount());");
    auto output = build(shader);
    ASSERT_TRUE(output) << firstMessage();
}

// --max-variants: a pass at the limit builds, one variant past it is refused before enumeration.
TEST_F(CompileDriverTest, APassAtTheVariantLimitBuildsAndOnePastIsRefused) {
    BuildOptions atLimit;
    atLimit.maxVariantsPerPass = 4;  // kTwoKeywordShader has 4 variants
    EXPECT_TRUE(build(kTwoKeywordShader, atLimit));
    BuildOptions pastLimit;
    pastLimit.maxVariantsPerPass = 3;
    EXPECT_FALSE(build(kTwoKeywordShader, pastLimit));
    ASSERT_TRUE(mDiagnostics.hasErrors());
    const Diagnostic& error = mDiagnostics.diagnostics().back();
    EXPECT_NE(error.message.find("has 4 variants (2 keyword sets); the limit is 3"),
              std::string::npos)
        << error.message;
    EXPECT_EQ(error.notes.size(), 2u);
}

}  // namespace
}  // namespace varc::driver
