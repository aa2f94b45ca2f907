// SPDX-License-Identifier: Apache-2.0
// Which keywords Unity's built-in pipeline enables for a light in a given pass (docs/KEYWORDS.md
// §9).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace varc::variants {

enum class LightType { Directional, Point, Spot };
enum class ShadowMode { None, Hard, Soft };
// The pass kinds whose keywords depend on the light being drawn.
enum class LightPassKind { ForwardBase, ForwardAdd, DeferredLight };

struct LightDescription {
    LightType type = LightType::Directional;
    bool cookie = false;
    ShadowMode shadows = ShadowMode::None;
    int vertexLightCount = 0;  // ForwardBase: point lights shaded per vertex (VERTEXLIGHT_ON)
    bool hdr = false;          // camera HDR (UNITY_HDR_ON in deferred passes)
    bool lightProbes = false;  // ForwardBase: object samples SH (LIGHTPROBE_SH)
    // ForwardBase, the object's lightmaps (docs/KEYWORDS.md §9): LIGHTMAP_ON,
    // DIRLIGHTMAP_COMBINED, DYNAMICLIGHTMAP_ON, SHADOWS_SHADOWMASK, LIGHTMAP_SHADOW_MIXING.
    bool lightmap = false;
    bool dirLightmap = false;
    bool dynamicLightmap = false;
    bool shadowmask = false;
    bool shadowMixing = false;
};

std::optional<LightType> parseLightType(std::string_view name);
std::optional<ShadowMode> parseShadowMode(std::string_view name);
// From a LightMode tag: "ForwardBase", "ForwardAdd", "Deferred"/"" light pass.
std::optional<LightPassKind> lightPassKindFromLightMode(std::string_view lightMode);

// The keywords Unity enables, sorted. Examples:
//   ForwardAdd, point + cookie              -> {POINT_COOKIE}
//   ForwardAdd, spot, hard shadows          -> {SHADOWS_DEPTH, SPOT}
//   ForwardBase, directional, 2 vertex lights -> {DIRECTIONAL, VERTEXLIGHT_ON}
//   ForwardBase, lightmap, 2 vertex lights    -> {DIRECTIONAL, LIGHTMAP_ON} (never both)
//   DeferredLight, point, soft, hdr         -> {POINT, SHADOWS_CUBE, SHADOWS_SOFT, UNITY_HDR_ON}
std::vector<std::string> lightKeywords(const LightDescription& light, LightPassKind pass);

}  // namespace varc::variants
