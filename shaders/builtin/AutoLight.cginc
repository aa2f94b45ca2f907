// SPDX-License-Identifier: Apache-2.0
// varc built-in: AutoLight.cginc. Per-light-type attenuation and shadow macros for forward
// passes: UNITY_LIGHT_ATTENUATION, LIGHT_ATTENUATION, LIGHTING_COORDS, TRANSFER_VERTEX_TO_FRAGMENT,
// SHADOW_COORDS/TRANSFER_SHADOW/SHADOW_ATTENUATION and the UNITY_SHADOW_* forms, selected by the
// variant's light keyword (POINT, SPOT, DIRECTIONAL, POINT_COOKIE, DIRECTIONAL_COOKIE) and shadow
// keyword (SHADOWS_SCREEN, SHADOWS_DEPTH, SHADOWS_CUBE, SHADOWS_SOFT). Attenuation formulas:
// docs/KEYWORDS.md §9 and docs/LIGHTING.md §3, §6; textures and matrices: docs/SHADER_ABI.md §5-§6.
// Written for varc.
#ifndef AUTOLIGHT_INCLUDED
#define AUTOLIGHT_INCLUDED

#include "HLSLSupport.cginc"
#include "UnityShaderVariables.cginc"
#include "UnityCG.cginc"
#include "UnityShadowLibrary.cginc"

// No light keyword: the pass renders the main directional light (ForwardBase).
#if !defined(POINT) && !defined(SPOT) && !defined(DIRECTIONAL) && !defined(POINT_COOKIE) && !defined(DIRECTIONAL_COOKIE)
#define DIRECTIONAL 1
#endif

// =============================================================================================
// Shadows. With no shadow keyword every shadow term is exactly 1.
// =============================================================================================
#if defined(SHADOWS_SCREEN)
    // Main directional light: screen-space shadow mask, .r = shadow (strength applied, no fade).
    UNITY_DECLARE_SCREENSPACE_SHADOWMAP(_ShadowMapTexture);
    inline fixed unitySampleShadow(unityShadowCoord4 shadowCoord) {
        return UNITY_SAMPLE_SCREEN_SHADOW(_ShadowMapTexture, shadowCoord);
    }
    #define SHADOW_COORDS(idx1) unityShadowCoord4 _ShadowCoord : TEXCOORD##idx1;
    #define TRANSFER_SHADOW(a) a._ShadowCoord = ComputeScreenPos(a.pos);
    #define SHADOW_ATTENUATION(a) unitySampleShadow(a._ShadowCoord)
    #define VARC_REALTIME_SHADOW(a, worldPos) unitySampleShadow((a)._ShadowCoord)
#elif defined(SHADOWS_DEPTH) && defined(SPOT)
    #define SHADOW_COORDS(idx1) unityShadowCoord4 _ShadowCoord : TEXCOORD##idx1;
    #define TRANSFER_SHADOW(a) a._ShadowCoord = mul(unity_WorldToShadow[0], mul(unity_ObjectToWorld, v.vertex));
    #define SHADOW_ATTENUATION(a) UnitySampleShadowmap(a._ShadowCoord)
    #define VARC_REALTIME_SHADOW(a, worldPos) UnitySampleShadowmap(mul(unity_WorldToShadow[0], unityShadowCoord4(worldPos, 1)))
#elif defined(SHADOWS_CUBE)
    #define SHADOW_COORDS(idx1) unityShadowCoord3 _ShadowCoord : TEXCOORD##idx1;
    #define TRANSFER_SHADOW(a) a._ShadowCoord.xyz = mul(unity_ObjectToWorld, v.vertex).xyz - _LightPositionRange.xyz;
    #define SHADOW_ATTENUATION(a) UnitySampleShadowmap(a._ShadowCoord)
    #define VARC_REALTIME_SHADOW(a, worldPos) UnitySampleShadowmap((worldPos) - _LightPositionRange.xyz)
#else
    #define SHADOW_COORDS(idx1)
    #define TRANSFER_SHADOW(a)
    #define SHADOW_ATTENUATION(a) 1.0
#endif

#if defined(VARC_REALTIME_SHADOW)
    // Forward shadow with the distance fade: saturate(realtime + fade); fade metric per
    // UnityComputeShadowFadeDistance with the view depth of worldPos.
    inline half UnityComputeForwardShadows(half realtimeShadow, float3 worldPos) {
        float viewZ = dot(_WorldSpaceCameraPos - worldPos, UNITY_MATRIX_V[2].xyz);
        float fade = UnityComputeShadowFade(UnityComputeShadowFadeDistance(worldPos, viewZ));
        return saturate(realtimeShadow + fade);
    }
    #define UNITY_SHADOW_ATTENUATION(a, worldPos) UnityComputeForwardShadows(VARC_REALTIME_SHADOW(a, worldPos), worldPos)
#else
    #define UNITY_SHADOW_ATTENUATION(a, worldPos) 1.0
#endif
#define UNITY_SHADOW_COORDS(idx1) SHADOW_COORDS(idx1)
#define UNITY_TRANSFER_SHADOW(a, coord) TRANSFER_SHADOW(a)

// The forward shadow of a pixel from its position alone (Unity 2017.4+): the realtime shadow of
// the variant's light (screen-space mask at screenPos, spot map, point cube), faded with
// distance and mixed with the baked shadow mask at lightmapUV (UnityMixRealtimeAndBakedShadows).
half UnityComputeForwardShadows(float2 lightmapUV, float3 worldPos, float4 screenPos) {
    float viewZ = dot(_WorldSpaceCameraPos - worldPos, UNITY_MATRIX_V[2].xyz);
    float fade = UnityComputeShadowFade(UnityComputeShadowFadeDistance(worldPos, viewZ));
#if defined(SHADOWS_SCREEN)
    half realtime = unitySampleShadow(screenPos);
#elif defined(SHADOWS_DEPTH) && defined(SPOT)
    half realtime = UnitySampleShadowmap(mul(unity_WorldToShadow[0], unityShadowCoord4(worldPos, 1)));
#elif defined(SHADOWS_CUBE)
    half realtime = UnitySampleShadowmap(worldPos - _LightPositionRange.xyz);
#else
    half realtime = 1.0;
#endif
    return UnityMixRealtimeAndBakedShadows(realtime, UnitySampleBakedOcclusion(lightmapUV, worldPos), fade);
}

// The interpolated shadow coordinate as a float4 (point lights carry a direction: w = 1; no
// shadow: 0), for code that passes it on.
#if defined(SHADOWS_SCREEN) || (defined(SHADOWS_DEPTH) && defined(SPOT))
    #define READ_SHADOW_COORDS(a) (a)._ShadowCoord
#elif defined(SHADOWS_CUBE)
    #define READ_SHADOW_COORDS(a) unityShadowCoord4((a)._ShadowCoord.xyz, 1)
#else
    #define READ_SHADOW_COORDS(a) unityShadowCoord4(0, 0, 0, 0)
#endif
#define UNITY_READ_SHADOW_COORDS(input) READ_SHADOW_COORDS(input)

// =============================================================================================
// Light attenuation per light type (docs/LIGHTING.md §3). lc = unity_WorldToLight * worldPos.
//   POINT              tex2D(_LightTexture0, dot(lc,lc).rr).r                       * shadow
//   SPOT               (lc.z > 0) * tex2D(_LightTexture0, lc.xy/lc.w + 0.5).w
//                      * tex2D(_LightTextureB0, dot(lc.xyz,lc.xyz).rr).r            * shadow
//   POINT_COOKIE       tex2D(_LightTextureB0, dot(lc,lc).rr).r * texCUBE(_LightTexture0, lc).w * shadow
//   DIRECTIONAL_COOKIE tex2D(_LightTexture0, lc.xy).w                               * shadow
//   DIRECTIONAL        shadow
// dot(lc,lc) = d^2/range^2 indexes the falloff lookup (docs/LIGHTING.md §4, SHADER_ABI.md §6).
// =============================================================================================
#if defined(POINT)
    sampler2D_float _LightTexture0;
    #define DECLARE_LIGHT_COORDS(idx) unityShadowCoord3 _LightCoord : TEXCOORD##idx;
    #define COMPUTE_LIGHT_COORDS(a) a._LightCoord = mul(unity_WorldToLight, mul(unity_ObjectToWorld, v.vertex)).xyz;
    #define LIGHT_ATTENUATION(a) (tex2D(_LightTexture0, dot(a._LightCoord, a._LightCoord).rr).UNITY_ATTEN_CHANNEL * SHADOW_ATTENUATION(a))
    #define UNITY_LIGHT_ATTENUATION(destName, input, worldPos) \
        unityShadowCoord3 varc_lc_##destName = mul(unity_WorldToLight, unityShadowCoord4(worldPos, 1)).xyz; \
        fixed varc_shadow_##destName = UNITY_SHADOW_ATTENUATION(input, worldPos); \
        fixed destName = tex2D(_LightTexture0, dot(varc_lc_##destName, varc_lc_##destName).rr).UNITY_ATTEN_CHANNEL * varc_shadow_##destName;
#endif

#if defined(SPOT)
    sampler2D _LightTexture0;       // the spot cookie (alpha); a soft disc when none is set
    sampler2D_float _LightTextureB0; // the falloff lookup
    inline fixed UnitySpotCookie(unityShadowCoord4 LightCoord) {
        return tex2D(_LightTexture0, LightCoord.xy / LightCoord.w + 0.5).w;
    }
    inline fixed UnitySpotAttenuate(unityShadowCoord3 LightCoord) {
        return tex2D(_LightTextureB0, dot(LightCoord, LightCoord).xx).UNITY_ATTEN_CHANNEL;
    }
    #define DECLARE_LIGHT_COORDS(idx) unityShadowCoord4 _LightCoord : TEXCOORD##idx;
    #define COMPUTE_LIGHT_COORDS(a) a._LightCoord = mul(unity_WorldToLight, mul(unity_ObjectToWorld, v.vertex));
    #define LIGHT_ATTENUATION(a) ((a._LightCoord.z > 0) * UnitySpotCookie(a._LightCoord) * UnitySpotAttenuate(a._LightCoord.xyz) * SHADOW_ATTENUATION(a))
    #define UNITY_LIGHT_ATTENUATION(destName, input, worldPos) \
        unityShadowCoord4 varc_lc_##destName = mul(unity_WorldToLight, unityShadowCoord4(worldPos, 1)); \
        fixed varc_shadow_##destName = UNITY_SHADOW_ATTENUATION(input, worldPos); \
        fixed destName = (varc_lc_##destName.z > 0) * UnitySpotCookie(varc_lc_##destName) * UnitySpotAttenuate(varc_lc_##destName.xyz) * varc_shadow_##destName;
#endif

#if defined(DIRECTIONAL)
    #define DECLARE_LIGHT_COORDS(idx)
    #define COMPUTE_LIGHT_COORDS(a)
    #define LIGHT_ATTENUATION(a) SHADOW_ATTENUATION(a)
    #define UNITY_LIGHT_ATTENUATION(destName, input, worldPos) fixed destName = UNITY_SHADOW_ATTENUATION(input, worldPos);
#endif

#if defined(POINT_COOKIE)
    samplerCUBE_float _LightTexture0; // the cube cookie (alpha)
    sampler2D_float _LightTextureB0;  // the falloff lookup
    #define DECLARE_LIGHT_COORDS(idx) unityShadowCoord3 _LightCoord : TEXCOORD##idx;
    #define COMPUTE_LIGHT_COORDS(a) a._LightCoord = mul(unity_WorldToLight, mul(unity_ObjectToWorld, v.vertex)).xyz;
    #define LIGHT_ATTENUATION(a) (tex2D(_LightTextureB0, dot(a._LightCoord, a._LightCoord).rr).UNITY_ATTEN_CHANNEL * texCUBE(_LightTexture0, a._LightCoord).w * SHADOW_ATTENUATION(a))
    #define UNITY_LIGHT_ATTENUATION(destName, input, worldPos) \
        unityShadowCoord3 varc_lc_##destName = mul(unity_WorldToLight, unityShadowCoord4(worldPos, 1)).xyz; \
        fixed varc_shadow_##destName = UNITY_SHADOW_ATTENUATION(input, worldPos); \
        fixed destName = tex2D(_LightTextureB0, dot(varc_lc_##destName, varc_lc_##destName).rr).UNITY_ATTEN_CHANNEL * texCUBE(_LightTexture0, varc_lc_##destName).w * varc_shadow_##destName;
#endif

#if defined(DIRECTIONAL_COOKIE)
    sampler2D _LightTexture0;         // the directional cookie (alpha), repeating
    #define DECLARE_LIGHT_COORDS(idx) unityShadowCoord2 _LightCoord : TEXCOORD##idx;
    #define COMPUTE_LIGHT_COORDS(a) a._LightCoord = mul(unity_WorldToLight, mul(unity_ObjectToWorld, v.vertex)).xy;
    #define LIGHT_ATTENUATION(a) (tex2D(_LightTexture0, a._LightCoord).w * SHADOW_ATTENUATION(a))
    #define UNITY_LIGHT_ATTENUATION(destName, input, worldPos) \
        unityShadowCoord2 varc_lc_##destName = mul(unity_WorldToLight, unityShadowCoord4(worldPos, 1)).xy; \
        fixed varc_shadow_##destName = UNITY_SHADOW_ATTENUATION(input, worldPos); \
        fixed destName = tex2D(_LightTexture0, varc_lc_##destName).w * varc_shadow_##destName;
#endif

// Interpolator plumbing: light coordinates in TEXCOORD<idx1>, shadow coordinates in TEXCOORD<idx2>.
// The TRANSFER macros read the vertex input `v` (v.vertex) and, for screen shadows, `a.pos`.
#define LIGHTING_COORDS(idx1, idx2) DECLARE_LIGHT_COORDS(idx1) SHADOW_COORDS(idx2)
#define TRANSFER_VERTEX_TO_FRAGMENT(a) COMPUTE_LIGHT_COORDS(a) TRANSFER_SHADOW(a)
#define UNITY_LIGHTING_COORDS(idx1, idx2) DECLARE_LIGHT_COORDS(idx1) UNITY_SHADOW_COORDS(idx2)
#define UNITY_TRANSFER_LIGHTING(a, coord) COMPUTE_LIGHT_COORDS(a) UNITY_TRANSFER_SHADOW(a, coord)

// More of the light and shadow plumbing (issue #27).
// The w of a shadow coordinate as interpolated (no platform rescales it here).
#define UNITY_SHADOW_W(_w) _w
// The shadow coordinate from a world position instead of the vertex input `v` (2021.3+).
#if defined(SHADOWS_SCREEN)
    #define TRANSFER_SHADOW_WPOS(a, wpos) TRANSFER_SHADOW(a)
#elif defined(SHADOWS_DEPTH) && defined(SPOT)
    #define TRANSFER_SHADOW_WPOS(a, wpos) a._ShadowCoord = mul(unity_WorldToShadow[0], unityShadowCoord4((wpos).xyz, 1));
#elif defined(SHADOWS_CUBE)
    #define TRANSFER_SHADOW_WPOS(a, wpos) a._ShadowCoord.xyz = (wpos).xyz - _LightPositionRange.xyz;
#else
    #define TRANSFER_SHADOW_WPOS(a, wpos)
#endif
// `lightCoord`: the light-space coordinate of |worldPos| for the variant's light type, as the
// attenuation of that type reads it (none for a directional light without cookie).
#if defined(POINT) || defined(POINT_COOKIE)
    #define DECLARE_LIGHT_COORD(input, worldPos) unityShadowCoord3 lightCoord = mul(unity_WorldToLight, unityShadowCoord4(worldPos, 1)).xyz
#elif defined(SPOT)
    #define DECLARE_LIGHT_COORD(input, worldPos) unityShadowCoord4 lightCoord = mul(unity_WorldToLight, unityShadowCoord4(worldPos, 1))
#elif defined(DIRECTIONAL_COOKIE)
    #define DECLARE_LIGHT_COORD(input, worldPos) unityShadowCoord2 lightCoord = mul(unity_WorldToLight, unityShadowCoord4(worldPos, 1)).xy
#else
    #define DECLARE_LIGHT_COORD(input, worldPos)
#endif

#endif // AUTOLIGHT_INCLUDED
