// SPDX-License-Identifier: Apache-2.0
// Which keywords Unity's built-in pipeline enables for a light in a given pass (docs/KEYWORDS.md
// §9).
#include "varc/variants/LightKeywords.h"

#include <algorithm>

#include "varc/core/AsciiCase.h"
#include "varc/variants/RuntimeKeywords.h"

namespace varc::variants {

namespace {

// §4.2 table: spot lights always have a cookie, so there is no SPOT_COOKIE.
const char* lightTypeKeyword(const LightDescription& light) {
    switch (light.type) {
        case LightType::Directional:
            return light.cookie ? "DIRECTIONAL_COOKIE" : "DIRECTIONAL";
        case LightType::Point:
            return light.cookie ? "POINT_COOKIE" : "POINT";
        case LightType::Spot:
            return "SPOT";
    }
    return "DIRECTIONAL";
}

// §4.2: SCREEN for directional, DEPTH for spot, CUBE for point. SHADOWS_SOFT only where the
// pass filters a shadow map itself (spot, point): directional soft filtering happens in the
// screen-space collector, matching the 13-variant lightpass model (SOFT => DEPTH or CUBE).
void addShadowKeywords(const LightDescription& light, std::vector<std::string>& keywords) {
    if (light.shadows == ShadowMode::None) return;
    switch (light.type) {
        case LightType::Directional:
            keywords.emplace_back("SHADOWS_SCREEN");
            return;
        case LightType::Spot:
            keywords.emplace_back("SHADOWS_DEPTH");
            break;
        case LightType::Point:
            keywords.emplace_back("SHADOWS_CUBE");
            break;
    }
    if (light.shadows == ShadowMode::Soft) keywords.emplace_back("SHADOWS_SOFT");
}

// §4.1: DIRECTIONAL is always defined. Only an uncookied directional light is the base-pass
// light; any other light is drawn by ForwardAdd, so its shadows do not set SHADOWS_SCREEN here.
void addForwardBaseKeywords(const LightDescription& light, std::vector<std::string>& keywords) {
    keywords.emplace_back("DIRECTIONAL");
    bool mainDirectional = light.type == LightType::Directional && !light.cookie;
    if (mainDirectional && light.shadows != ShadowMode::None)
        keywords.emplace_back("SHADOWS_SCREEN");
    // fwdbase's rule VERTEXLIGHT_ON => !LIGHTMAP_ON: a lightmapped object has no vertex lights.
    if (light.vertexLightCount > 0 && !light.lightmap) keywords.emplace_back("VERTEXLIGHT_ON");
    if (light.lightProbes) keywords.emplace_back("LIGHTPROBE_SH");
    if (light.lightmap) keywords.emplace_back("LIGHTMAP_ON");
    if (light.dirLightmap && (light.lightmap || light.dynamicLightmap))
        keywords.emplace_back("DIRLIGHTMAP_COMBINED");
    if (light.dynamicLightmap) keywords.emplace_back("DYNAMICLIGHTMAP_ON");
    if (light.shadowmask) keywords.emplace_back("SHADOWS_SHADOWMASK");
    if (light.shadowMixing && (light.lightmap || light.shadowmask))
        keywords.emplace_back("LIGHTMAP_SHADOW_MIXING");
}

}  // namespace

std::optional<LightType> parseLightType(std::string_view name) {
    if (equalsIgnoreAsciiCase(name, "directional")) return LightType::Directional;
    if (equalsIgnoreAsciiCase(name, "point")) return LightType::Point;
    if (equalsIgnoreAsciiCase(name, "spot")) return LightType::Spot;
    return std::nullopt;
}

std::optional<ShadowMode> parseShadowMode(std::string_view name) {
    if (equalsIgnoreAsciiCase(name, "none")) return ShadowMode::None;
    if (equalsIgnoreAsciiCase(name, "hard")) return ShadowMode::Hard;
    if (equalsIgnoreAsciiCase(name, "soft")) return ShadowMode::Soft;
    return std::nullopt;
}

std::optional<LightPassKind> lightPassKindFromLightMode(std::string_view lightMode) {
    if (equalsIgnoreAsciiCase(lightMode, "ForwardBase")) return LightPassKind::ForwardBase;
    if (equalsIgnoreAsciiCase(lightMode, "ForwardAdd")) return LightPassKind::ForwardAdd;
    if (lightMode.empty() || equalsIgnoreAsciiCase(lightMode, "Deferred")) {
        return LightPassKind::DeferredLight;
    }
    return std::nullopt;
}

std::vector<std::string> lightKeywords(const LightDescription& light, LightPassKind pass) {
    std::vector<std::string> keywords;
    switch (pass) {
        case LightPassKind::ForwardBase:
            addForwardBaseKeywords(light, keywords);
            break;
        case LightPassKind::ForwardAdd:
            keywords.emplace_back(lightTypeKeyword(light));
            addShadowKeywords(light, keywords);
            break;
        case LightPassKind::DeferredLight:
            keywords.emplace_back(lightTypeKeyword(light));
            addShadowKeywords(light, keywords);
            if (light.hdr) keywords.emplace_back(kHdrKeyword);
            break;
    }
    std::sort(keywords.begin(), keywords.end());
    return keywords;
}

}  // namespace varc::variants
