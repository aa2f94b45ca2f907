// SPDX-License-Identifier: Apache-2.0
// lightKeywords: every light type x cookie x shadow mode per pass kind (docs/KEYWORDS.md §9).
#include <gtest/gtest.h>

#include <algorithm>

#include "VariantsTestSupport.h"
#include "varc/variants/LightKeywords.h"
#include "varc/variants/VariantSelector.h"

namespace varc::variants {
namespace {

using Names = std::vector<std::string>;

struct Case {
    LightType type;
    bool cookie;
    ShadowMode shadows;
    Names expected;  // ForwardAdd / DeferredLight without HDR
};

// Spot lights always carry a cookie, so |cookie| does not change their keyword. Directional
// soft shadows are filtered by the screen-space collector: no SHADOWS_SOFT (docs/KEYWORDS.md).
const std::vector<Case> kLightPassCases = {
    {LightType::Directional, false, ShadowMode::None, {"DIRECTIONAL"}},
    {LightType::Directional, false, ShadowMode::Hard, {"DIRECTIONAL", "SHADOWS_SCREEN"}},
    {LightType::Directional, false, ShadowMode::Soft, {"DIRECTIONAL", "SHADOWS_SCREEN"}},
    {LightType::Directional, true, ShadowMode::None, {"DIRECTIONAL_COOKIE"}},
    {LightType::Directional, true, ShadowMode::Hard, {"DIRECTIONAL_COOKIE", "SHADOWS_SCREEN"}},
    {LightType::Directional, true, ShadowMode::Soft, {"DIRECTIONAL_COOKIE", "SHADOWS_SCREEN"}},
    {LightType::Point, false, ShadowMode::None, {"POINT"}},
    {LightType::Point, false, ShadowMode::Hard, {"POINT", "SHADOWS_CUBE"}},
    {LightType::Point, false, ShadowMode::Soft, {"POINT", "SHADOWS_CUBE", "SHADOWS_SOFT"}},
    {LightType::Point, true, ShadowMode::None, {"POINT_COOKIE"}},
    {LightType::Point, true, ShadowMode::Hard, {"POINT_COOKIE", "SHADOWS_CUBE"}},
    {LightType::Point, true, ShadowMode::Soft, {"POINT_COOKIE", "SHADOWS_CUBE", "SHADOWS_SOFT"}},
    {LightType::Spot, false, ShadowMode::None, {"SPOT"}},
    {LightType::Spot, false, ShadowMode::Hard, {"SHADOWS_DEPTH", "SPOT"}},
    {LightType::Spot, false, ShadowMode::Soft, {"SHADOWS_DEPTH", "SHADOWS_SOFT", "SPOT"}},
    {LightType::Spot, true, ShadowMode::None, {"SPOT"}},
    {LightType::Spot, true, ShadowMode::Hard, {"SHADOWS_DEPTH", "SPOT"}},
    {LightType::Spot, true, ShadowMode::Soft, {"SHADOWS_DEPTH", "SHADOWS_SOFT", "SPOT"}},
};

LightDescription describe(const Case& c) {
    LightDescription light;
    light.type = c.type;
    light.cookie = c.cookie;
    light.shadows = c.shadows;
    return light;
}

TEST(LightKeywords, ForwardAddForEveryTypeCookieAndShadowMode) {
    for (const Case& c : kLightPassCases) {
        LightDescription light = describe(c);
        light.vertexLightCount = 3;  // ignored by the add pass
        light.hdr = true;            // ignored by the add pass
        EXPECT_EQ(lightKeywords(light, LightPassKind::ForwardAdd), c.expected);
    }
}

TEST(LightKeywords, DeferredLightAddsHdr) {
    for (const Case& c : kLightPassCases) {
        LightDescription light = describe(c);
        EXPECT_EQ(lightKeywords(light, LightPassKind::DeferredLight), c.expected);
        light.hdr = true;
        Names withHdr = c.expected;
        withHdr.push_back("UNITY_HDR_ON");  // sorts last among these names
        EXPECT_EQ(lightKeywords(light, LightPassKind::DeferredLight), withHdr);
    }
}

TEST(LightKeywords, ForwardBaseAlwaysDefinesDirectional) {
    for (const Case& c : kLightPassCases) {
        LightDescription light = describe(c);
        bool mainShadows =
            c.type == LightType::Directional && !c.cookie && c.shadows != ShadowMode::None;
        Names expected =
            mainShadows ? Names{"DIRECTIONAL", "SHADOWS_SCREEN"} : Names{"DIRECTIONAL"};
        EXPECT_EQ(lightKeywords(light, LightPassKind::ForwardBase), expected);
    }
}

TEST(LightKeywords, ForwardBaseVertexLightsAndProbes) {
    LightDescription light;
    light.shadows = ShadowMode::Soft;
    light.vertexLightCount = 2;
    light.lightProbes = true;
    EXPECT_EQ(lightKeywords(light, LightPassKind::ForwardBase),
              (Names{"DIRECTIONAL", "LIGHTPROBE_SH", "SHADOWS_SCREEN", "VERTEXLIGHT_ON"}));
    light.vertexLightCount = 0;
    light.shadows = ShadowMode::None;
    EXPECT_EQ(lightKeywords(light, LightPassKind::ForwardBase),
              (Names{"DIRECTIONAL", "LIGHTPROBE_SH"}));
}

// Every request the light model makes must be a real variant of the matching shortcut, so
// strict selection never fails for built-in lights.
void expectStrictHits(const std::vector<std::string>& pragmas, LightPassKind pass, bool hdr) {
    VariantSpace space = testing::spaceOf(pragmas).value();
    std::vector<VariantKey> variants = space.enumerate();
    for (const Case& c : kLightPassCases) {
        for (int vertexLights : {0, 4}) {
            LightDescription light = describe(c);
            light.hdr = hdr;
            light.vertexLightCount = vertexLights;
            VariantKey requested = space.table().keyOf(lightKeywords(light, pass));
            EXPECT_TRUE(selectVariant(variants, requested, SelectionPolicy::Strict).exact)
                << ::testing::PrintToString(lightKeywords(light, pass));
        }
    }
}

TEST(LightKeywords, RequestsAreExactVariantsOfTheShortcuts) {
    expectStrictHits({"multi_compile_fwdadd"}, LightPassKind::ForwardAdd, false);
    expectStrictHits({"multi_compile_fwdadd_fullshadows"}, LightPassKind::ForwardAdd, false);
    expectStrictHits({"multi_compile_lightpass", "multi_compile ___ UNITY_HDR_ON"},
                     LightPassKind::DeferredLight, true);
    expectStrictHits({"multi_compile_lightpass", "multi_compile ___ UNITY_HDR_ON"},
                     LightPassKind::DeferredLight, false);
    expectStrictHits({"multi_compile_fwdbase"}, LightPassKind::ForwardBase, false);
}

TEST(LightKeywords, ForwardBaseLightmapsDropVertexLights) {
    LightDescription light;
    light.vertexLightCount = 2;
    light.lightmap = true;
    light.dirLightmap = true;
    light.shadowMixing = true;
    EXPECT_EQ(lightKeywords(light, LightPassKind::ForwardBase),
              (Names{"DIRECTIONAL", "DIRLIGHTMAP_COMBINED", "LIGHTMAP_ON",
                     "LIGHTMAP_SHADOW_MIXING"}));
    light.lightmap = false;  // no lightmap: the direction and the mixing have nothing to act on
    EXPECT_EQ(lightKeywords(light, LightPassKind::ForwardBase),
              (Names{"DIRECTIONAL", "VERTEXLIGHT_ON"}));
}

// Every combination of the ForwardBase inputs is an exact fwdbase variant, and together they
// reach all 136: the renderer can draw every variant of the shortcut.
TEST(LightKeywords, ForwardBaseRequestsReachEveryFwdbaseVariant) {
    VariantSpace space = testing::spaceOf({"multi_compile_fwdbase"}).value();
    std::vector<VariantKey> variants = space.enumerate();
    std::vector<bool> reached(variants.size(), false);
    for (unsigned bits = 0; bits < 256; ++bits) {
        LightDescription light;
        light.shadows = (bits & 1) ? ShadowMode::Hard : ShadowMode::None;
        light.vertexLightCount = (bits & 2) ? 1 : 0;
        light.lightProbes = bits & 4;
        light.lightmap = bits & 8;
        light.dirLightmap = bits & 16;
        light.dynamicLightmap = bits & 32;
        light.shadowmask = bits & 64;
        light.shadowMixing = bits & 128;
        VariantKey requested =
            space.table().keyOf(lightKeywords(light, LightPassKind::ForwardBase));
        Selection selection = selectVariant(variants, requested, SelectionPolicy::Strict);
        ASSERT_TRUE(selection.exact) << bits;
        reached[*selection.index] = true;
    }
    EXPECT_EQ(variants.size(), 136u);
    EXPECT_EQ(std::count(reached.begin(), reached.end(), true), 136);
}

TEST(LightKeywords, ParsesNamesCaseInsensitively) {
    EXPECT_EQ(parseLightType("Directional"), LightType::Directional);
    EXPECT_EQ(parseLightType("point"), LightType::Point);
    EXPECT_EQ(parseLightType("SPOT"), LightType::Spot);
    EXPECT_EQ(parseLightType("area"), std::nullopt);
    EXPECT_EQ(parseShadowMode("none"), ShadowMode::None);
    EXPECT_EQ(parseShadowMode("Hard"), ShadowMode::Hard);
    EXPECT_EQ(parseShadowMode("soft"), ShadowMode::Soft);
    EXPECT_EQ(parseShadowMode("pcf"), std::nullopt);
}

TEST(LightKeywords, PassKindFromLightMode) {
    EXPECT_EQ(lightPassKindFromLightMode("ForwardBase"), LightPassKind::ForwardBase);
    EXPECT_EQ(lightPassKindFromLightMode("FORWARDADD"), LightPassKind::ForwardAdd);
    EXPECT_EQ(lightPassKindFromLightMode("Deferred"), LightPassKind::DeferredLight);
    EXPECT_EQ(lightPassKindFromLightMode(""), LightPassKind::DeferredLight);
    EXPECT_EQ(lightPassKindFromLightMode("ShadowCaster"), std::nullopt);
}

}  // namespace
}  // namespace varc::variants
