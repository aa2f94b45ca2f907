// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityPBSLighting.cginc. Entry point of the physically based lighting library:
// UNITY_BRDF_PBS (docs/LIGHTING.md §2), UnityLight/UnityIndirect, the metallic/specular helpers,
// the shadow library, and the Standard lighting functions for surface-style outputs.
// It declares no light textures (_LightTexture0 etc.): shaders that include it may declare them
// with the type their light needs (seed 002). Written for varc; not derived from Unity's file.
#ifndef UNITY_PBS_LIGHTING_INCLUDED
#define UNITY_PBS_LIGHTING_INCLUDED

#include "UnityShaderVariables.cginc"
#include "UnityCG.cginc"
#include "UnityLightingCommon.cginc"
#include "UnityStandardUtils.cginc"
#include "UnityStandardBRDF.cginc"
#include "UnityShadowLibrary.cginc"
#include "UnityGlobalIllumination.cginc" // added for third-party shaders
#include "UnityGBuffer.cginc"              // the _Deferred lighting functions

// UNITY_BRDF_PBS(diffColor, specColor, oneMinusReflectivity, smoothness, normal, viewDir, light, gi)
// A shader may #define UNITY_BRDF_PBS itself before including this file. The scalar arguments
// are cast so that vector arguments truncate as in HLSL (glslang rejects vector->scalar
// argument conversion; seed 002 passes a float3 smoothness).
#if !defined(UNITY_BRDF_PBS)
#define UNITY_BRDF_PBS(diffColor, specColor, oneMinusReflectivity, smoothness, normal, viewDir, light, gi) \
    BRDF1_Unity_PBS(diffColor, specColor, (half)(oneMinusReflectivity), (half)(smoothness), normal, viewDir, light, gi)
#endif

// Extra indirect light of Unity 5's "separate" directional lightmaps (DIRLIGHTMAP_SEPARATE,
// removed in 2017): varc has no such lightmaps, so the term is zero in every variant.
inline half3 BRDF_Unity_Indirect(half3 baseColor, half3 specColor, half oneMinusReflectivity, half smoothness,
                                 half3 normal, half3 viewDir, half occlusion, UnityGI gi) {
    return half3(0, 0, 0);
}
#if !defined(UNITY_BRDF_GI)
#define UNITY_BRDF_GI BRDF_Unity_Indirect
#endif

// Surface-shader GI of a SurfaceOutputStandard(Specular) s: the probe lookup data from its
// smoothness and normal, then UnityGlobalIllumination (diffuse only in deferred passes whose
// reflections come from the reflection buffers).
#define UNITY_GLOSSY_ENV_FROM_SURFACE(x, s, data) \
    Unity_GlossyEnvironmentData x = UnityGlossyEnvironmentSetup(s.Smoothness, data.worldViewDir, s.Normal, half3(0, 0, 0));
#if defined(UNITY_PASS_DEFERRED) && UNITY_ENABLE_REFLECTION_BUFFERS
#define UNITY_GI(x, s, data) x = UnityGlobalIllumination(data, s.Occlusion, s.Normal);
#else
#define UNITY_GI(x, s, data) \
    UNITY_GLOSSY_ENV_FROM_SURFACE(g, s, data); \
    x = UnityGlobalIllumination(data, s.Occlusion, s.Normal, g);
#endif

// ---------------------------------------------------------------------------------------------
// Surface outputs and the Standard lighting functions (forward use).
// ---------------------------------------------------------------------------------------------
struct SurfaceOutputStandard {
    fixed3 Albedo;
    float3 Normal;      // world space, unit length
    half3 Emission;
    half Metallic;
    half Smoothness;
    half Occlusion;
    fixed Alpha;
};
struct SurfaceOutputStandardSpecular {
    fixed3 Albedo;
    fixed3 Specular;
    float3 Normal;
    half3 Emission;
    half Smoothness;
    half Occlusion;
    fixed Alpha;
};

inline half4 LightingStandard(SurfaceOutputStandard s, float3 viewDir, UnityGI gi) {
    s.Normal = normalize(s.Normal);
    half oneMinusReflectivity;
    half3 specColor;
    s.Albedo = DiffuseAndSpecularFromMetallic(s.Albedo, s.Metallic, specColor, oneMinusReflectivity);
    half outputAlpha;
    s.Albedo = PreMultiplyAlpha(s.Albedo, s.Alpha, oneMinusReflectivity, outputAlpha);
    half4 c = UNITY_BRDF_PBS(s.Albedo, specColor, oneMinusReflectivity, s.Smoothness, s.Normal, viewDir, gi.light, gi.indirect);
    c.a = outputAlpha;
    return c;
}
inline half4 LightingStandardSpecular(SurfaceOutputStandardSpecular s, float3 viewDir, UnityGI gi) {
    s.Normal = normalize(s.Normal);
    half oneMinusReflectivity;
    s.Albedo = EnergyConservationBetweenDiffuseAndSpecular(s.Albedo, s.Specular, oneMinusReflectivity);
    half outputAlpha;
    s.Albedo = PreMultiplyAlpha(s.Albedo, s.Alpha, oneMinusReflectivity, outputAlpha);
    half4 c = UNITY_BRDF_PBS(s.Albedo, s.Specular, oneMinusReflectivity, s.Smoothness, s.Normal, viewDir, gi.light, gi.indirect);
    c.a = outputAlpha;
    return c;
}

// GI hooks of the Standard models (surface-shader style): diffuse GI plus the reflection probes
// sampled with the surface's smoothness.
inline void LightingStandard_GI(SurfaceOutputStandard s, UnityGIInput data, inout UnityGI gi) {
    Unity_GlossyEnvironmentData g = UnityGlossyEnvironmentSetup(s.Smoothness, data.worldViewDir, s.Normal, lerp(unity_ColorSpaceDielectricSpec.rgb, s.Albedo, s.Metallic));
    gi = UnityGlobalIllumination(data, s.Occlusion, s.Normal, g);
}
inline void LightingStandardSpecular_GI(SurfaceOutputStandardSpecular s, UnityGIInput data, inout UnityGI gi) {
    Unity_GlossyEnvironmentData g = UnityGlossyEnvironmentSetup(s.Smoothness, data.worldViewDir, s.Normal, s.Specular);
    gi = UnityGlobalIllumination(data, s.Occlusion, s.Normal, g);
}

// Deferred (G-buffer) forms of the Standard lighting functions: the surface goes to the G-buffer
// (UnityStandardDataToGbuffer: diffuse colour and occlusion, specular colour and smoothness,
// normal) and the return value is what the G-buffer pass adds to the emission target: the
// lighting of |gi| (its light is black in a G-buffer pass, leaving the indirect part) plus
// s.Emission, alpha 1.
inline half4 LightingStandard_Deferred(SurfaceOutputStandard s, float3 viewDir, UnityGI gi,
                                       out half4 outGBuffer0, out half4 outGBuffer1, out half4 outGBuffer2) {
    half oneMinusReflectivity;
    half3 specColor;
    s.Albedo = DiffuseAndSpecularFromMetallic(s.Albedo, s.Metallic, specColor, oneMinusReflectivity);
    half4 c = UNITY_BRDF_PBS(s.Albedo, specColor, oneMinusReflectivity, s.Smoothness, s.Normal, viewDir, gi.light, gi.indirect);
    UnityStandardData data;
    data.diffuseColor = s.Albedo;
    data.occlusion = s.Occlusion;
    data.specularColor = specColor;
    data.smoothness = s.Smoothness;
    data.normalWorld = s.Normal;
    UnityStandardDataToGbuffer(data, outGBuffer0, outGBuffer1, outGBuffer2);
    return half4(c.rgb + s.Emission, 1);
}
inline half4 LightingStandardSpecular_Deferred(SurfaceOutputStandardSpecular s, float3 viewDir, UnityGI gi,
                                               out half4 outGBuffer0, out half4 outGBuffer1, out half4 outGBuffer2) {
    half oneMinusReflectivity;
    s.Albedo = EnergyConservationBetweenDiffuseAndSpecular(s.Albedo, s.Specular, oneMinusReflectivity);
    half4 c = UNITY_BRDF_PBS(s.Albedo, s.Specular, oneMinusReflectivity, s.Smoothness, s.Normal, viewDir, gi.light, gi.indirect);
    UnityStandardData data;
    data.diffuseColor = s.Albedo;
    data.occlusion = s.Occlusion;
    data.specularColor = s.Specular;
    data.smoothness = s.Smoothness;
    data.normalWorld = s.Normal;
    UnityStandardDataToGbuffer(data, outGBuffer0, outGBuffer1, outGBuffer2);
    return half4(c.rgb + s.Emission, 1);
}

#endif // UNITY_PBS_LIGHTING_INCLUDED
