// SPDX-License-Identifier: Apache-2.0
// planPass: a project's staged counts (declared -> materials -> settings -> rules) per pass,
// hand-computed, and the PassType of a LightMode.
#include <gtest/gtest.h>

#include "varc/frontend/ShaderLoader.h"
#include "varc/frontend/VariantPlan.h"
#include "varc/includes/FileSystem.h"

namespace varc::frontend {
namespace {

// Two passes: FORWARD (ForwardBase) declares
//   multi_compile _ FOG_EXP2 (2) x multi_compile _ INSTANCING_ON (2) x shader_feature _ _DETAIL (2)
// = 8 variants; SHADOW (ShadowCaster) declares shader_feature _ _DETAIL = 2.
constexpr const char* kShader = R"(Shader "Test/Plan" { SubShader {
Pass { Name "FORWARD" Tags { "LightMode" = "ForwardBase" }
CGPROGRAM
#pragma vertex v
#pragma fragment f
#pragma multi_compile _ FOG_EXP2
#pragma multi_compile _ INSTANCING_ON
#pragma shader_feature _ _DETAIL
float4 v(float4 p : POSITION) : SV_POSITION { return p; }
float4 f() : SV_Target { return 0; }
ENDCG }
Pass { Name "SHADOW" Tags { "LightMode" = "ShadowCaster" }
CGPROGRAM
#pragma vertex v
#pragma fragment f
#pragma shader_feature _ _DETAIL
float4 v(float4 p : POSITION) : SV_POSITION { return p; }
float4 f() : SV_Target { return 0; }
ENDCG }
} }
)";

class VariantPlanTest : public ::testing::Test {
protected:
    void SetUp() override {
        mFileSystem.add("plan.shader", kShader);
        auto shader = loadShader("plan.shader", mFileSystem, mSourceMap, {}, mDiagnostics);
        ASSERT_TRUE(shader.has_value());
        mShader.emplace(std::move(*shader));
        ASSERT_EQ(mShader->passes.size(), 2u);
    }

    VariantPlan plan(size_t pass, const ShaderDemand& demand,
                     const std::vector<variants::StripRule>& rules = {}, uint64_t limit = 1000) {
        return planPass(*mShader, mShader->passes[pass], demand, rules, limit);
    }

    static variants::KeywordRequest material(std::vector<std::string> keywords) {
        return {variants::RequestKind::Material, "M.mat", std::move(keywords)};
    }

    includes::InMemoryFileSystem mFileSystem;
    includes::SourceMap mSourceMap;
    DiagnosticList mDiagnostics;
    std::optional<LoadedShader> mShader;
};

TEST_F(VariantPlanTest, StagesCountMaterialsThenSettingsThenRules) {
    ShaderDemand demand;
    demand.requests = {material({"_DETAIL"})};  // pins _DETAIL on: 2 x 2 x 1 = 4
    variants::StripRule instancing;
    instancing.name = "instancing stripping";
    instancing.with = {"INSTANCING_ON"};  // removes the 2 with INSTANCING_ON
    demand.settingsRules = {instancing};
    variants::StripRule fog;
    fog.name = "no exp2 in forward";
    fog.pass = "forward";
    fog.with = {"FOG_EXP2"};  // removes 1 of the 2 left
    VariantPlan forward = plan(0, demand, {fog});
    EXPECT_EQ(forward.counts.declared, 8u);
    EXPECT_EQ(forward.counts.materials, 4u);
    EXPECT_EQ(forward.counts.settings, 2u);
    EXPECT_EQ(forward.counts.rules, 1u);
    EXPECT_EQ(forward.settingsRemoved, (std::vector<uint64_t>{2}));
    EXPECT_EQ(forward.rulesRemoved, (std::vector<uint64_t>{1}));
    ASSERT_EQ(forward.keys.size(), 1u);
    EXPECT_EQ(mShader->passes[0].space->table().namesOf(forward.keys[0]),
              (std::vector<std::string>{"_DETAIL"}));

    // The rule names the FORWARD pass only; the shadow pass keeps its one variant.
    VariantPlan shadow = plan(1, demand, {fog});
    EXPECT_EQ(shadow.counts.declared, 2u);
    EXPECT_EQ(shadow.counts.rules, 1u);  // _DETAIL on, pinned by the material
    EXPECT_EQ(shadow.rulesRemoved, (std::vector<uint64_t>{0}));
}

TEST_F(VariantPlanTest, AlwaysIncludedShipsEverythingTheRulesLeave) {
    ShaderDemand demand;
    demand.alwaysIncluded = true;
    VariantPlan forward = plan(0, demand);
    EXPECT_EQ(forward.counts.materials, 8u);
    EXPECT_EQ(forward.counts.rules, 8u);
    EXPECT_EQ(forward.keys.size(), 8u);
}

TEST_F(VariantPlanTest, OverTheLimitNothingIsEnumerated) {
    ShaderDemand demand;
    demand.alwaysIncluded = true;
    VariantPlan forward = plan(0, demand, {}, /*limit=*/7);
    EXPECT_FALSE(forward.enumerated);
    EXPECT_TRUE(forward.keys.empty());
    EXPECT_EQ(forward.counts.materials, 8u);
    EXPECT_EQ(forward.counts.rules, 8u);  // later stages not applied: equal to materials
}

TEST_F(VariantPlanTest, CollectionEntriesReachOnlyPassesOfTheirPassType) {
    ShaderDemand demand;
    // PassType 8 = ShadowCaster: _DETAIL on in the shadow pass only.
    demand.collectionRequests.push_back(
        {8, {variants::RequestKind::CollectionVariant, "W.shadervariants", {"_DETAIL"}}});
    VariantPlan shadow = plan(1, demand);
    VariantPlan forward = plan(0, demand);
    // No material: the all-off combination ships, plus the entry's in the shadow pass.
    EXPECT_EQ(shadow.counts.materials, 2u);
    EXPECT_EQ(forward.counts.materials, 4u);  // 2 x 2 x {_} only
}

TEST(PassType, LightModesMapToUnitysPassTypes) {
    EXPECT_EQ(passTypeOfLightMode(""), 0);
    EXPECT_EQ(passTypeOfLightMode("Always"), 0);
    EXPECT_EQ(passTypeOfLightMode("ForwardBase"), 4);
    EXPECT_EQ(passTypeOfLightMode("forwardadd"), 5);
    EXPECT_EQ(passTypeOfLightMode("ShadowCaster"), 8);
    EXPECT_EQ(passTypeOfLightMode("Deferred"), 10);
    EXPECT_EQ(passTypeOfLightMode("Meta"), 11);
    EXPECT_EQ(passTypeOfLightMode("UniversalForward"), 13);
}

}  // namespace
}  // namespace varc::frontend
