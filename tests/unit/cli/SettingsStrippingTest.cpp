// SPDX-License-Identifier: Apache-2.0
// Graphics Settings' lightmap, fog and instancing stripping as strip rules (docs/PROJECTS.md).
#include <gtest/gtest.h>

#include "varc/cli/SettingsStripping.h"

namespace varc::cli {
namespace {

std::vector<std::string> names(const std::vector<variants::StripRule>& rules) {
    std::vector<std::string> result;
    for (const variants::StripRule& rule : rules) result.push_back(rule.name);
    return result;
}

TEST(SettingsStripping, WithoutASettingsFileOnlyUnusedInstancingIsStripped) {
    auto rules = settingsStripRules(std::nullopt, /*anyMaterialInstanced=*/false, {});
    ASSERT_EQ(rules.size(), 1u);
    EXPECT_EQ(rules[0].with, (std::vector<std::string>{"INSTANCING_ON"}));
    EXPECT_TRUE(settingsStripRules(std::nullopt, /*anyMaterialInstanced=*/true, {}).empty());
}

TEST(SettingsStripping, AutomaticModesKeepEveryLightmapAndFogMode) {
    project::GraphicsSettings settings;
    settings.lightmapStripping = 0;
    settings.fogStripping = 0;
    settings.fogKeepExp2 = false;  // ignored: only Custom reads the flags
    settings.instancingStripping = 2;  // Keep All
    EXPECT_TRUE(settingsStripRules(settings, false, {}).empty());
}

TEST(SettingsStripping, CustomModesStripWhatIsNotKept) {
    project::GraphicsSettings settings;
    settings.lightmapStripping = 1;
    settings.lightmapKeepPlain = true;
    settings.lightmapKeepDirCombined = false;
    settings.lightmapKeepShadowMask = false;  // the other flags are missing: kept
    settings.fogStripping = 1;
    settings.fogKeepLinear = true;
    settings.fogKeepExp = false;
    settings.fogKeepExp2 = false;
    settings.instancingStripping = 1;  // Strip All, even with an instanced material
    SourceLocation where{3, 0, 0};
    auto rules = settingsStripRules(settings, /*anyMaterialInstanced=*/true, where);
    EXPECT_EQ(names(rules),
              (std::vector<std::string>{
                  "lightmap stripping: m_LightmapKeepDirCombined is 0",
                  "lightmap stripping: m_LightmapKeepShadowMask is 0",
                  "lightmap stripping: DIRLIGHTMAP_COMBINED without a lightmap",
                  "fog stripping: FOG_EXP not kept", "fog stripping: FOG_EXP2 not kept",
                  "instancing stripping: Strip All"}));
    EXPECT_EQ(rules[0].with, (std::vector<std::string>{"LIGHTMAP_ON", "DIRLIGHTMAP_COMBINED"}));
    EXPECT_EQ(rules[2].without, (std::vector<std::string>{"LIGHTMAP_ON", "DYNAMICLIGHTMAP_ON"}));
    for (const variants::StripRule& rule : rules) EXPECT_EQ(rule.location.file, 3u);
}

}  // namespace
}  // namespace varc::cli
