// SPDX-License-Identifier: Apache-2.0
// Graphics Settings' lightmap, fog and instancing stripping as strip rules.
#include "varc/cli/SettingsStripping.h"

#include <string>
#include <utility>

namespace varc::cli {

namespace {

constexpr int kAutomatic = 0, kCustom = 1;
constexpr int kStripUnused = 0, kStripAll = 1;

variants::StripRule rule(std::string name, SourceLocation where, std::vector<std::string> with,
                         std::vector<std::string> without = {}) {
    variants::StripRule made;
    made.name = std::move(name);
    made.location = where;
    made.with = std::move(with);
    made.without = std::move(without);
    return made;
}

// Custom lightmap modes: keep a variant only if every lightmap feature it uses is kept.
void addLightmapRules(const project::GraphicsSettings& settings, SourceLocation where,
                      std::vector<variants::StripRule>& rules) {
    struct Mode {
        const std::optional<bool>& keep;
        const char* flag;
        std::vector<std::string> with, without;
    };
    const Mode modes[] = {
        {settings.lightmapKeepPlain, "m_LightmapKeepPlain", {"LIGHTMAP_ON"},
         {"DIRLIGHTMAP_COMBINED"}},
        {settings.lightmapKeepDirCombined, "m_LightmapKeepDirCombined",
         {"LIGHTMAP_ON", "DIRLIGHTMAP_COMBINED"}, {}},
        {settings.lightmapKeepDynamicPlain, "m_LightmapKeepDynamicPlain", {"DYNAMICLIGHTMAP_ON"},
         {"DIRLIGHTMAP_COMBINED"}},
        {settings.lightmapKeepDynamicDirCombined, "m_LightmapKeepDynamicDirCombined",
         {"DYNAMICLIGHTMAP_ON", "DIRLIGHTMAP_COMBINED"}, {}},
        {settings.lightmapKeepShadowMask, "m_LightmapKeepShadowMask", {"SHADOWS_SHADOWMASK"}, {}},
        {settings.lightmapKeepSubtractive, "m_LightmapKeepSubtractive", {"LIGHTMAP_SHADOW_MIXING"},
         {"SHADOWS_SHADOWMASK"}},
    };
    for (const Mode& mode : modes) {
        if (mode.keep.value_or(true)) continue;
        rules.push_back(rule(std::string("lightmap stripping: ") + mode.flag + " is 0", where,
                             mode.with, mode.without));
    }
    // Directional lightmap data without a lightmap is meaningless (docs/PROJECTS.md; Unity's exact predicate is unpublished).
    rules.push_back(rule("lightmap stripping: DIRLIGHTMAP_COMBINED without a lightmap", where,
                         {"DIRLIGHTMAP_COMBINED"}, {"LIGHTMAP_ON", "DYNAMICLIGHTMAP_ON"}));
}

void addFogRules(const project::GraphicsSettings& settings, SourceLocation where,
                 std::vector<variants::StripRule>& rules) {
    const std::pair<const std::optional<bool>&, const char*> modes[] = {
        {settings.fogKeepLinear, "FOG_LINEAR"},
        {settings.fogKeepExp, "FOG_EXP"},
        {settings.fogKeepExp2, "FOG_EXP2"}};
    for (const auto& [keep, keyword] : modes) {
        if (keep.value_or(true)) continue;
        rules.push_back(rule(std::string("fog stripping: ") + keyword + " not kept", where,
                             {keyword}));
    }
}

}  // namespace

std::vector<variants::StripRule> settingsStripRules(
    const std::optional<project::GraphicsSettings>& settings, bool anyMaterialInstanced,
    SourceLocation where) {
    std::vector<variants::StripRule> rules;
    if (settings && settings->lightmapStripping.value_or(kAutomatic) == kCustom) {
        addLightmapRules(*settings, where, rules);
    }
    if (settings && settings->fogStripping.value_or(kAutomatic) == kCustom) {
        addFogRules(*settings, where, rules);
    }
    int instancing = settings ? settings->instancingStripping.value_or(kStripUnused) : kStripUnused;
    if (instancing == kStripAll) {
        rules.push_back(rule("instancing stripping: Strip All", where, {"INSTANCING_ON"}));
    } else if (instancing == kStripUnused && !anyMaterialInstanced) {
        rules.push_back(rule("instancing stripping: no material of the shader enables instancing",
                             where, {"INSTANCING_ON"}));
    }
    return rules;
}

}  // namespace varc::cli
