// SPDX-License-Identifier: Apache-2.0
// ObjectLightmaps: which of Unity's ForwardBase lightmap and light-probe keywords an object's
// draws select, from its lightmap, its light-probe setting and the scene's mixed lighting mode
// (docs/SCENES.md "Lightmaps", docs/KEYWORDS.md §9).
#pragma once

#include "varc/scene/Scene.h"

namespace varc::scene {

struct ObjectLightmaps {
    bool lightmap = false;         // LIGHTMAP_ON: a baked lightmap
    bool dirLightmap = false;      // DIRLIGHTMAP_COMBINED: the lightmaps are directional
    bool dynamicLightmap = false;  // DYNAMICLIGHTMAP_ON: a realtime (Enlighten) lightmap
    bool shadowmask = false;       // SHADOWS_SHADOWMASK: shadowmask modes, every object
    bool shadowMixing = false;     // LIGHTMAP_SHADOW_MIXING: shadowmask, or subtractive + lightmap
    bool lightProbes = false;      // LIGHTPROBE_SH
    // Vertex lights are allowed (Unity never combines them with LIGHTMAP_ON).
    bool vertexLights() const { return !lightmap; }
};

// |object|'s keywords in |scene|. Mixed modes: baked_indirect adds nothing; subtractive adds
// LIGHTMAP_SHADOW_MIXING to lightmapped objects; shadowmask adds SHADOWS_SHADOWMASK and
// LIGHTMAP_SHADOW_MIXING to every object; distance_shadowmask SHADOWS_SHADOWMASK alone.
// Example: a baked lightmap with a direction in shadowmask mode ->
// {lightmap, dirLightmap, shadowmask, shadowMixing}.
ObjectLightmaps objectLightmaps(const Scene& scene, const Object& object);

}  // namespace varc::scene
