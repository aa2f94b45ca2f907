// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityGlobalIllumination.cginc. Gathers the indirect lighting of a surface point
// into UnityGI: the pixel light scaled by attenuation, diffuse from light-probe SH and lightmaps,
// specular from the (box-projected, blended) reflection probes. Textures and parameters:
// docs/SHADER_ABI.md §4.13. Written for varc from the documented behaviour; not derived from
// Unity's file.
#ifndef UNITY_GLOBAL_ILLUMINATION_INCLUDED
#define UNITY_GLOBAL_ILLUMINATION_INCLUDED

#include "UnityCG.cginc"
#include "UnityLightingCommon.cginc"
#include "UnityStandardUtils.cginc"
#include "UnityImageBasedLighting.cginc"
#include "UnityShadowLibrary.cginc"

inline void ResetUnityLight(out UnityLight outLight) {
    outLight.color = half3(0, 0, 0);
    outLight.dir = half3(0, 1, 0);
    outLight.ndotl = 0;
}
inline void ResetUnityGI(out UnityGI outGI) {
    ResetUnityLight(outGI.light);
    outGI.indirect.diffuse = 0;
    outGI.indirect.specular = 0;
}

// UnitySampleBakedOcclusion: UnityShadowLibrary.cginc (as in Unity).

// Diffuse GI: light colour * atten; SH (per pixel, plus data.ambient) when the pass samples SH;
// baked and realtime lightmaps when their keywords are on; everything times occlusion.
// varc does not mix realtime shadows into baked lighting (no subtractive mode).
inline UnityGI UnityGI_Base(UnityGIInput data, half occlusion, half3 normalWorld) {
    UnityGI o_gi;
    ResetUnityGI(o_gi);
    o_gi.light = data.light;
    o_gi.light.color *= data.atten;
#if UNITY_SHOULD_SAMPLE_SH
    o_gi.indirect.diffuse = ShadeSHPerPixel(normalWorld, data.ambient, data.worldPos);
#endif
#if defined(LIGHTMAP_ON)
    half4 bakedColorTex = UNITY_SAMPLE_TEX2D(unity_Lightmap, data.lightmapUV.xy);
    half3 bakedColor = DecodeLightmap(bakedColorTex);
    #if defined(DIRLIGHTMAP_COMBINED)
        fixed4 bakedDirTex = UNITY_SAMPLE_TEX2D_SAMPLER(unity_LightmapInd, unity_Lightmap, data.lightmapUV.xy);
        o_gi.indirect.diffuse += DecodeDirectionalLightmap(bakedColor, bakedDirTex, normalWorld);
    #else
        o_gi.indirect.diffuse += bakedColor;
    #endif
#endif
#if defined(DYNAMICLIGHTMAP_ON)
    fixed4 realtimeColorTex = UNITY_SAMPLE_TEX2D(unity_DynamicLightmap, data.lightmapUV.zw);
    half3 realtimeColor = DecodeRealtimeLightmap(realtimeColorTex);
    #if defined(DIRLIGHTMAP_COMBINED)
        half4 realtimeDirTex = UNITY_SAMPLE_TEX2D_SAMPLER(unity_DynamicDirectionality, unity_DynamicLightmap, data.lightmapUV.zw);
        o_gi.indirect.diffuse += DecodeDirectionalLightmap(realtimeColor, realtimeDirTex, normalWorld);
    #else
        o_gi.indirect.diffuse += realtimeColor;
    #endif
#endif
    o_gi.indirect.diffuse *= occlusion;
    return o_gi;
}

// Specular GI: probe 0 (box-projected when its ProbePosition.w > 0), blended towards probe 1 by
// 1 - boxMin[0].w; unity_IndirectSpecColor when glossy reflections are off.
inline half3 UnityGI_IndirectSpecular(UnityGIInput data, half occlusion, Unity_GlossyEnvironmentData glossIn) {
    half3 specular;
#if defined(_GLOSSYREFLECTIONS_OFF)
    specular = unity_IndirectSpecColor.rgb;
#else
    half3 originalReflUVW = glossIn.reflUVW;
    #if defined(UNITY_SPECCUBE_BOX_PROJECTION)
    glossIn.reflUVW = BoxProjectedCubemapDirection(originalReflUVW, data.worldPos, data.probePosition[0], data.boxMin[0], data.boxMax[0]);
    #endif
    half3 env0 = Unity_GlossyEnvironment(UNITY_PASS_TEXCUBE(unity_SpecCube0), data.probeHDR[0], glossIn);
    #if defined(UNITY_SPECCUBE_BLENDING)
    const float kBlendFactor = 0.99999;
    float blendLerp = data.boxMin[0].w;
    UNITY_BRANCH
    if (blendLerp < kBlendFactor) {
        #if defined(UNITY_SPECCUBE_BOX_PROJECTION)
        glossIn.reflUVW = BoxProjectedCubemapDirection(originalReflUVW, data.worldPos, data.probePosition[1], data.boxMin[1], data.boxMax[1]);
        #endif
        half3 env1 = Unity_GlossyEnvironment(UNITY_PASS_TEXCUBE_SAMPLER(unity_SpecCube1, unity_SpecCube0), data.probeHDR[1], glossIn);
        specular = lerp(env1, env0, blendLerp);
    } else {
        specular = env0;
    }
    #else
    specular = env0;
    #endif
#endif
    return specular * occlusion;
}
// Unity 5.4 signature (the normal was unused).
inline half3 UnityGI_IndirectSpecular(UnityGIInput data, half occlusion, half3 normalWorld, Unity_GlossyEnvironmentData glossIn) {
    return UnityGI_IndirectSpecular(data, occlusion, glossIn);
}

inline UnityGI UnityGlobalIllumination(UnityGIInput data, half occlusion, half3 normalWorld) {
    return UnityGI_Base(data, occlusion, normalWorld);
}
inline UnityGI UnityGlobalIllumination(UnityGIInput data, half occlusion, half3 normalWorld, Unity_GlossyEnvironmentData glossIn) {
    UnityGI o_gi = UnityGI_Base(data, occlusion, normalWorld);
    o_gi.indirect.specular = UnityGI_IndirectSpecular(data, occlusion, glossIn);
    return o_gi;
}
// Unity 5.x signatures: the reflection lookup set up from the smoothness (roughness 1 - s, the
// view reflected about the normal); without |reflections|, diffuse GI only (specular black).
inline UnityGI UnityGlobalIllumination(UnityGIInput data, half occlusion, half smoothness, half3 normalWorld, bool reflections) {
    if (!reflections) return UnityGI_Base(data, occlusion, normalWorld);
    Unity_GlossyEnvironmentData g = UnityGlossyEnvironmentSetup(smoothness, data.worldViewDir, normalWorld, half3(0, 0, 0));
    return UnityGlobalIllumination(data, occlusion, normalWorld, g);
}
inline UnityGI UnityGlobalIllumination(UnityGIInput data, half occlusion, half smoothness, half3 normalWorld) {
    return UnityGlobalIllumination(data, occlusion, smoothness, normalWorld, true);
}

// Subtractive lighting mode: the main light is baked into the lightmap, so a realtime shadow
// must darken it. The light's estimated contribution where it is shadowed,
// NdotL * (1 - attenuation) * _LightColor0, is subtracted, kept above unity_ShadowColor, faded
// back to the lightmap by _LightShadowData.x (1 - shadow strength), and never brighter than
// the lightmap.
inline half3 SubtractMainLightWithRealtimeAttenuationFromLightmap(half3 lightmap, half attenuation, half4 bakedColorTex, half3 normalWorld) {
    half ndotl = saturate(dot(normalWorld, _WorldSpaceLightPos0.xyz));
    half3 estimatedShadowedLight = ndotl * (1 - attenuation) * _LightColor0.rgb;
    half3 realtimeShadow = max(lightmap - estimatedShadowedLight, unity_ShadowColor.rgb);
    realtimeShadow = lerp(realtimeShadow, lightmap, _LightShadowData.x);
    return min(lightmap, realtimeShadow);
}

// Unity 5's "separate" directional lightmaps, which split a lightmap texel into a directional
// light for the specular BRDF and a non-directional remainder. The direction is
// dirTex.xyz * 2 - 1 and its length d in [0, 1] the directional share: o_light gets colour
// color * d, the unit direction and its NdotL; the function returns the remainder
// color * (1 - d). (varc's lightmaps are never in this format; realtimeNormalTex, the normal
// Unity's realtime GI used for them, is not needed for this split.)
inline half3 DecodeDirectionalSpecularLightmap(half3 color, half4 dirTex, half3 normalWorld, bool isRealtimeLightmap,
                                              fixed4 realtimeNormalTex, out UnityLight o_light) {
    half3 dir = dirTex.xyz * 2 - 1;
    half d = saturate(length(dir));
    o_light.dir = d > 0 ? dir / max(length(dir), 1e-4) : normalWorld;
    o_light.color = color * d;
    o_light.ndotl = saturate(dot(normalWorld, o_light.dir));
    return color * (1 - d);
}

#endif // UNITY_GLOBAL_ILLUMINATION_INCLUDED
