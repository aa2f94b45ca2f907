// SPDX-License-Identifier: Apache-2.0
// Built-in shortcuts: every shortcut's count and exact enumeration order, rules and options.
#include <gtest/gtest.h>

#include <iterator>
#include <set>
#include <sstream>

#include "VariantsTestSupport.h"
#include "varc/variants/Shortcuts.h"

namespace varc::variants {
namespace {

using testing::listing;
using testing::spaceOf;
using Listing = std::vector<std::string>;

Listing listingOf(const std::vector<std::string>& pragmas) {
    std::optional<VariantSpace> space = spaceOf(pragmas);
    if (!space) return {};
    EXPECT_EQ(space->count(), listing(*space).size());
    return listing(*space);
}

std::set<std::string> wordsOf(const std::string& line) {
    std::istringstream stream(line);
    return {std::istream_iterator<std::string>(stream), std::istream_iterator<std::string>()};
}

uint64_t countOf(const std::vector<std::string>& pragmas) {
    std::optional<VariantSpace> space = spaceOf(pragmas);
    if (!space) return 0;
    EXPECT_EQ(space->count(), space->enumerate().size());
    return space->count();
}

const Listing kFullShadows13 = {
    "POINT",
    "DIRECTIONAL",
    "SPOT",
    "POINT_COOKIE",
    "DIRECTIONAL_COOKIE",
    "SHADOWS_DEPTH SPOT",
    "DIRECTIONAL SHADOWS_SCREEN",
    "DIRECTIONAL_COOKIE SHADOWS_SCREEN",
    "POINT SHADOWS_CUBE",
    "POINT_COOKIE SHADOWS_CUBE",
    "SHADOWS_DEPTH SHADOWS_SOFT SPOT",
    "POINT SHADOWS_CUBE SHADOWS_SOFT",
    "POINT_COOKIE SHADOWS_CUBE SHADOWS_SOFT",
};

const Listing kFwdBase4 = {
    "DIRECTIONAL",
    "DIRECTIONAL LIGHTPROBE_SH",
    "DIRECTIONAL SHADOWS_SCREEN",
    "DIRECTIONAL LIGHTPROBE_SH SHADOWS_SCREEN",
};

const std::string kSkipLightmaps =
    "skip_variants LIGHTMAP_ON DIRLIGHTMAP_COMBINED DYNAMICLIGHTMAP_ON SHADOWS_SHADOWMASK "
    "LIGHTMAP_SHADOW_MIXING";

TEST(Shortcuts, TableHasEveryShortcut) {
    std::vector<std::string> names;
    for (const Shortcut& shortcut : builtinShortcuts()) names.push_back(shortcut.name);
    EXPECT_EQ(names, (Listing{"fwdadd", "fwdadd_fullshadows", "lightpass", "fwdbase",
                              "fwdbasealpha", "fwdbase_fullshadows", "prepassfinal", "shadowcaster", "shadowcollector",
                              "fog", "instancing", "particles"}));
    ASSERT_NE(findShortcut("fog"), nullptr);
    EXPECT_EQ(findShortcut("fog")->directive(), "multi_compile_fog");
    EXPECT_EQ(findShortcut("multi_compile_fog"), nullptr);
    EXPECT_EQ(findShortcutOption("noshadow")->removes.size(), 4u);
    EXPECT_EQ(findShortcutOption("nothing"), nullptr);
}

// Not in Unity's manual but compiled by Unity: the base pass's shadows are fwdbase's already.
TEST(Shortcuts, FwdBaseFullShadowsListsTheSameVariantsAsFwdBase) {
    EXPECT_EQ(listingOf({"multi_compile_fwdbase_fullshadows"}), listingOf({"multi_compile_fwdbase"}));
    EXPECT_FALSE(listingOf({"multi_compile_fwdbase_fullshadows"}).empty());
}

TEST(Shortcuts, FwdAddIsFiveLightTypesInUnityOrder) {
    EXPECT_EQ(listingOf({"multi_compile_fwdadd"}),
              (Listing{"POINT", "DIRECTIONAL", "SPOT", "POINT_COOKIE", "DIRECTIONAL_COOKIE"}));
}

TEST(Shortcuts, FwdAddFullShadowsIsTheObserved13InOrder) {
    EXPECT_EQ(listingOf({"multi_compile_fwdadd_fullshadows"}), kFullShadows13);
    EXPECT_EQ(spaceOf({"multi_compile_fwdadd_fullshadows"})->fullCount(), 40u);
}

TEST(Shortcuts, LightPassIsTheSame13AndDoublesWithHdr) {
    EXPECT_EQ(listingOf({"multi_compile_lightpass"}), kFullShadows13);
    Listing hdr = listingOf({"multi_compile_lightpass", "multi_compile ___ UNITY_HDR_ON"});
    ASSERT_EQ(hdr.size(), 26u);
    EXPECT_EQ(hdr[0], "POINT");
    EXPECT_EQ(hdr[1], "POINT UNITY_HDR_ON");
    EXPECT_EQ(hdr[25], "POINT_COOKIE SHADOWS_CUBE SHADOWS_SOFT UNITY_HDR_ON");
}

TEST(Shortcuts, ShadowCasterIsDepthThenCube) {
    EXPECT_EQ(listingOf({"multi_compile_shadowcaster"}),
              (Listing{"SHADOWS_DEPTH", "SHADOWS_CUBE"}));
}

TEST(Shortcuts, FwdBaseWithoutLightmapsIsTheObserved8InOrder) {
    Listing expected = kFwdBase4;
    for (const std::string& line : kFwdBase4) expected.push_back(line + " VERTEXLIGHT_ON");
    EXPECT_EQ(listingOf({"multi_compile_fwdbase", kSkipLightmaps}), expected);
}

TEST(Shortcuts, FwdBaseWithoutVertexLightsIsTheObserved4) {
    EXPECT_EQ(listingOf({kSkipLightmaps, "multi_compile_fwdbase", "skip_variants VERTEXLIGHT_ON"}),
              kFwdBase4);
}

TEST(Shortcuts, FwdBaseFullSpaceFollowsTheRules) {
    std::optional<VariantSpace> space = spaceOf({"multi_compile_fwdbase"});
    ASSERT_TRUE(space);
    EXPECT_EQ(space->fullCount(), 256u);
    EXPECT_EQ(space->count(), 136u);
    Listing all = listing(*space);
    ASSERT_EQ(all.size(), 136u);
    EXPECT_EQ(all[0], "DIRECTIONAL");
    for (const std::string& line : all) {
        std::set<std::string> on = wordsOf(line);
        EXPECT_EQ(on.count("DIRECTIONAL"), 1u) << line;
        EXPECT_FALSE(on.count("LIGHTMAP_ON") && on.count("VERTEXLIGHT_ON")) << line;
        EXPECT_TRUE(!on.count("DIRLIGHTMAP_COMBINED") || on.count("LIGHTMAP_ON") ||
                    on.count("DYNAMICLIGHTMAP_ON"))
            << line;
        EXPECT_TRUE(!on.count("LIGHTMAP_SHADOW_MIXING") || on.count("LIGHTMAP_ON") ||
                    on.count("SHADOWS_SHADOWMASK"))
            << line;
    }
    EXPECT_EQ(std::set<std::string>(all.begin(), all.end()).size(), all.size());
}

TEST(Shortcuts, FwdBaseOptionsRemoveTheirKeywords) {
    // Unity's manual example: only SHADOWS_SCREEN, the shadowmask pair and LIGHTPROBE_SH vary.
    std::optional<VariantSpace> space =
        spaceOf({"multi_compile_fwdbase nolightmap nodirlightmap nodynlightmap novertexlight"});
    ASSERT_TRUE(space);
    EXPECT_EQ(space->count(), 12u);
    EXPECT_EQ(space->table().names(),
              (Listing{"DIRECTIONAL", "LIGHTMAP_SHADOW_MIXING", "LIGHTPROBE_SH", "SHADOWS_SCREEN",
                       "SHADOWS_SHADOWMASK"}));
    EXPECT_EQ(countOf({"multi_compile_fwdbase nolightmap nodirlightmap nodynlightmap novertexlight "
                       "noshadowmask"}),
              4u);
    EXPECT_EQ(spaceOf({"multi_compile_fwdbase noshadow"})->table().indexOf("SHADOWS_SCREEN"),
              std::nullopt);
}

TEST(Shortcuts, FullShadowsWithNoShadowIsFwdAdd) {
    EXPECT_EQ(listingOf({"multi_compile_fwdadd_fullshadows noshadow"}),
              listingOf({"multi_compile_fwdadd"}));
    EXPECT_EQ(countOf({"multi_compile_shadowcaster noshadow"}), 1u);
}

TEST(Shortcuts, FwdBaseAlphaHasNoShadowKeywords) {
    std::optional<VariantSpace> space = spaceOf({"multi_compile_fwdbasealpha"});
    ASSERT_TRUE(space);
    EXPECT_EQ(space->count(), 28u);
    EXPECT_EQ(space->table().indexOf("SHADOWS_SCREEN"), std::nullopt);
    EXPECT_EQ(space->table().indexOf("SHADOWS_SHADOWMASK"), std::nullopt);
    EXPECT_EQ(listingOf({"multi_compile_fwdbasealpha", kSkipLightmaps}),
              (Listing{"DIRECTIONAL", "DIRECTIONAL LIGHTPROBE_SH", "DIRECTIONAL VERTEXLIGHT_ON",
                       "DIRECTIONAL LIGHTPROBE_SH VERTEXLIGHT_ON"}));
}

TEST(Shortcuts, PrepassFinalHasAnAllOffVariantAnd56Variants) {
    Listing all = listingOf({"multi_compile_prepassfinal"});
    ASSERT_EQ(all.size(), 56u);  // 64 minus DIRLIGHTMAP_COMBINED alone (2^3)
    EXPECT_EQ(all[0], "");
    EXPECT_EQ(all[1], "LIGHTPROBE_SH");
    EXPECT_EQ(spaceOf({"multi_compile_prepassfinal"})->fullCount(), 64u);
}

TEST(Shortcuts, FogIsOffThenThreeModes) {
    EXPECT_EQ(listingOf({"multi_compile_fog"}), (Listing{"", "FOG_LINEAR", "FOG_EXP", "FOG_EXP2"}));
}

TEST(Shortcuts, InstancingIsTwoOrThreeWithProcedural) {
    EXPECT_EQ(listingOf({"multi_compile_instancing"}), (Listing{"", "INSTANCING_ON"}));
    EXPECT_EQ(listingOf({"instancing_options procedural:setup", "multi_compile_instancing"}),
              (Listing{"", "INSTANCING_ON", "PROCEDURAL_INSTANCING_ON"}));
}

TEST(Shortcuts, ParticlesIsTwo) {
    EXPECT_EQ(listingOf({"multi_compile_particles"}), (Listing{"", "SOFTPARTICLES_ON"}));
}

TEST(Shortcuts, ShadowCollectorIsTwoIndependentSets) {
    EXPECT_EQ(listingOf({"multi_compile_shadowcollector"}),
              (Listing{"", "SHADOWS_SINGLE_CASCADE", "SHADOWS_SPLIT_SPHERES",
                       "SHADOWS_SINGLE_CASCADE SHADOWS_SPLIT_SPHERES"}));
}

TEST(Shortcuts, SkippingALightTypeRemovesItsShadowVariants) {
    // SHADOWS_DEPTH needs SPOT; with SPOT skipped no SHADOWS_DEPTH variant is left.
    EXPECT_EQ(
        listingOf({"multi_compile_fwdadd_fullshadows", "skip_variants SPOT"}),
        (Listing{"POINT", "DIRECTIONAL", "POINT_COOKIE", "DIRECTIONAL_COOKIE",
                 "DIRECTIONAL SHADOWS_SCREEN", "DIRECTIONAL_COOKIE SHADOWS_SCREEN",
                 "POINT SHADOWS_CUBE", "POINT_COOKIE SHADOWS_CUBE",
                 "POINT SHADOWS_CUBE SHADOWS_SOFT", "POINT_COOKIE SHADOWS_CUBE SHADOWS_SOFT"}));
}

TEST(Shortcuts, ExpandShortcutDropsSetsLeftWithoutKeywords) {
    std::vector<const ShortcutOption*> options = {findShortcutOption("noshadow")};
    ShortcutExpansion expansion =
        expandShortcut(*findShortcut("lightpass"), options, SourceLocation{1, 2, 3});
    ASSERT_EQ(expansion.sets.size(), 1u);
    EXPECT_EQ(expansion.sets[0].keywords.size(), 5u);
    EXPECT_EQ(expansion.sets[0].directive, "multi_compile_lightpass");
    EXPECT_EQ(expansion.sets[0].location, (SourceLocation{1, 2, 3}));
    EXPECT_EQ(expansion.rules.size(), 4u);
}

}  // namespace
}  // namespace varc::variants
