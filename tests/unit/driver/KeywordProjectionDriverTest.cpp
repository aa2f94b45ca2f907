// SPDX-License-Identifier: Apache-2.0
// The compile driver with the keyword projection: one preprocessing per distinct projection of
// each stage, and the same programs and variant tables as without it.
#include <gtest/gtest.h>

#include "varc/driver/CompileDriver.h"
#include "varc/frontend/ShaderLoader.h"
#include "varc/includes/FileSystem.h"

namespace varc::driver {
namespace {

// Four keywords (16 variants). The vertex stage macro splits the stages; per stage, KW_A
// decides whether KW_B is looked up, KW_C always is, KW_D only in a branch never taken:
// (1 + 2) x 2 = 6 projections per stage, 12 in all; but the fragment stage's entry point
// does not reach `vert`, so with BuildOptions::projectReachableCode it has one: 7 in all.
constexpr const char* kShader = R"(Shader "Test/Projection" {
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile _ KW_A
            #pragma multi_compile _ KW_B
            #pragma multi_compile _ KW_C
            #pragma multi_compile _ KW_D
            #define SCALE_B 2
            #ifdef SHADER_STAGE_VERTEX
            float4 _VertexOnly;
            #endif
            float4 vert(float4 p : POSITION) : SV_POSITION {
            #if defined(KW_A)
            #  if KW_B
                p.x *= SCALE_B;
            #  endif
            #elif 0
                p.y += KW_D;
            #endif
            #ifndef KW_C
                p.z = 0;
            #endif
                return p;
            }
            float4 frag() : SV_Target { return float4(1, 1, 1, 1); }
            ENDCG
        }
    }
}
)";

class KeywordProjectionDriverTest : public ::testing::Test {
protected:
    std::optional<BuildOutput> build(const BuildOptions& options, std::string text = kShader) {
        mFileSystem.add("shaders/test.shader", text);
        auto shader =
            frontend::loadShader("shaders/test.shader", mFileSystem, mSourceMap, {}, mDiagnostics);
        if (!shader) return std::nullopt;
        mShaders.clear();
        mShaders.push_back(std::move(*shader));
        return buildPrograms(mShaders, mSourceMap, options, mDiagnostics);
    }

    includes::InMemoryFileSystem mFileSystem;
    includes::SourceMap mSourceMap;
    DiagnosticList mDiagnostics;
    std::vector<frontend::LoadedShader> mShaders;
};

BuildOptions everyLookup() {
    BuildOptions options;
    options.projectReachableCode = false;
    return options;
}

TEST_F(KeywordProjectionDriverTest, PreprocessesOncePerDistinctProjection) {
    for (const auto& [options, projections] : {std::pair{everyLookup(), 12u}, {{}, 7u}}) {
        auto output = build(options);
        ASSERT_TRUE(output);
        ASSERT_EQ(output->passes.size(), 1u);
        EXPECT_EQ(output->passes[0].variants.size(), 16u);
        EXPECT_EQ(output->unprojectedStages, 0u);
        EXPECT_EQ(output->keywordProjections, projections);
        EXPECT_EQ(output->projectionWalks, output->keywordProjections);
        EXPECT_EQ(output->preprocessedPrograms, output->keywordProjections);
    }
}

TEST_F(KeywordProjectionDriverTest, StagesTheTextCannotTellApartShareTheirProjections) {
    std::string text = kShader;
    const std::string stageTest = "#ifdef SHADER_STAGE_VERTEX";
    text.replace(text.find(stageTest), stageTest.size(), "#ifdef NOT_A_STAGE_MACRO");
    auto output = build(everyLookup(), text);  // (reachability starts at each stage's entry)
    ASSERT_TRUE(output);
    EXPECT_EQ(output->keywordProjections, 6u);  // one tree for both stages
    EXPECT_EQ(output->projectionWalks, 6u);
    EXPECT_EQ(output->preprocessedPrograms, 6u);
}

TEST_F(KeywordProjectionDriverTest, ChangesNoProgramAndNoVariantTable) {
    BuildOptions off;
    off.projectKeywords = false;
    for (const BuildOptions& on : {BuildOptions{}, everyLookup()}) {
        auto projected = build(on);
        auto observed = build(off);
        ASSERT_TRUE(projected && observed);
        // Without the projection every variant of each stage preprocesses on its own.
        EXPECT_EQ(observed->preprocessedPrograms, 32u);
        EXPECT_EQ(observed->keywordProjections, 0u);
        EXPECT_EQ(projected->compiledSources, observed->compiledSources);
        ASSERT_EQ(projected->programs.size(), observed->programs.size());
        for (size_t i = 0; i < observed->programs.size(); ++i)
            EXPECT_EQ(projected->programs[i].spirv, observed->programs[i].spirv) << "program " << i;
        EXPECT_EQ(projected->passes[0].variants, observed->passes[0].variants);
    }
}

}  // namespace
}  // namespace varc::driver
