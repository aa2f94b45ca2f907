// SPDX-License-Identifier: Apache-2.0
// varc built-in: Lighting.cginc. The legacy lighting models of Unity's surface shaders
// (Lambert, BlinnPhong) with their SurfaceOutput struct, on top of UnityLightingCommon
// (_LightColor0, _SpecColor, UnityLight/UnityGI). Formulas: docs/LIGHTING.md §2 (legacy models),
// restated at each function. Written for varc.
#ifndef LIGHTING_INCLUDED
#define LIGHTING_INCLUDED

#include "UnityLightingCommon.cginc"
#include "UnityCG.cginc"
#include "UnityGlobalIllumination.cginc" // UnityGIInput, UnityGlobalIllumination (added for third-party shaders)
#include "UnityGBuffer.cginc"

// The patch-constant output of tessellated surface shaders: three edge factors and one inside.
#ifdef UNITY_CAN_COMPILE_TESSELLATION
struct UnityTessellationFactors {
    float edge[3] : SV_TessFactor;
    float inside : SV_InsideTessFactor;
};
#endif

struct SurfaceOutput {
    fixed3 Albedo;
    fixed3 Normal;
    fixed3 Emission;
    half Specular;   // shininess exponent / 128
    fixed Gloss;     // specular intensity
    fixed Alpha;
};

// Lambert: albedo * light * max(0, N.L) + albedo * indirect diffuse.
inline fixed4 UnityLambertLight(SurfaceOutput s, UnityLight light) {
    fixed diff = max(0, dot(s.Normal, light.dir));
    fixed4 c;
    c.rgb = s.Albedo * light.color * diff;
    c.a = s.Alpha;
    return c;
}
inline fixed4 LightingLambert(SurfaceOutput s, UnityGI gi) {
    fixed4 c = UnityLambertLight(s, gi.light);
    c.rgb += s.Albedo * gi.indirect.diffuse;
    return c;
}

// Blinn-Phong: albedo * light * max(0, N.L) + light * _SpecColor * max(0, N.H)^(Specular*128) * Gloss.
inline fixed4 UnityBlinnPhongLight(SurfaceOutput s, half3 viewDir, UnityLight light) {
    half3 h = normalize(light.dir + viewDir);
    fixed diff = max(0, dot(s.Normal, light.dir));
    float nh = max(0, dot(s.Normal, h));
    float spec = pow(nh, s.Specular * 128.0) * s.Gloss;
    fixed4 c;
    c.rgb = s.Albedo * light.color * diff + light.color * _SpecColor.rgb * spec;
    c.a = s.Alpha;
    return c;
}
inline fixed4 LightingBlinnPhong(SurfaceOutput s, half3 viewDir, UnityGI gi) {
    fixed4 c = UnityBlinnPhongLight(s, viewDir, gi.light);
    c.rgb += s.Albedo * gi.indirect.diffuse;
    return c;
}

// GI hooks of the legacy models (surface-shader style): gather GI for the surface normal.
inline void LightingLambert_GI(SurfaceOutput s, UnityGIInput data, inout UnityGI gi) {
    gi = UnityGlobalIllumination(data, 1.0, s.Normal);
}
inline void LightingBlinnPhong_GI(SurfaceOutput s, UnityGIInput data, inout UnityGI gi) {
    gi = UnityGlobalIllumination(data, 1.0, s.Normal);
}

// Indirect light reaches the surface functions when the variant samples light probes or a
// lightmap (UNITY_SHOULD_SAMPLE_SH: UnityCG.cginc).
#if UNITY_SHOULD_SAMPLE_SH || defined(LIGHTMAP_ON) || defined(DYNAMICLIGHTMAP_ON)
#define UNITY_LIGHT_FUNCTION_APPLY_INDIRECT
#endif

// Deferred (G-buffer) forms of the legacy models, like LightingStandard_Deferred
// (UnityPBSLighting.cginc): the surface goes to the G-buffer and the return value is what the
// pass adds to the emission target, s.Emission plus (with indirect light) albedo * indirect
// diffuse, alpha 1. Lambert has no specular (black, smoothness 0); Blinn-Phong's specular colour
// is _SpecColor * Gloss and its smoothness the shininess s.Specular. Occlusion 1.
inline half4 VarcLegacyDeferred(SurfaceOutput s, UnityGI gi, half3 specColor, half smoothness,
                                out half4 outGBuffer0, out half4 outGBuffer1, out half4 outGBuffer2) {
    UnityStandardData data;
    data.diffuseColor = s.Albedo;
    data.occlusion = 1;
    data.specularColor = specColor;
    data.smoothness = smoothness;
    data.normalWorld = s.Normal;
    UnityStandardDataToGbuffer(data, outGBuffer0, outGBuffer1, outGBuffer2);
    half4 emission = half4(s.Emission, 1);
#ifdef UNITY_LIGHT_FUNCTION_APPLY_INDIRECT
    emission.rgb += s.Albedo * gi.indirect.diffuse;
#endif
    return emission;
}
inline half4 LightingLambert_Deferred(SurfaceOutput s, UnityGI gi, out half4 outGBuffer0, out half4 outGBuffer1, out half4 outGBuffer2) {
    return VarcLegacyDeferred(s, gi, 0, 0, outGBuffer0, outGBuffer1, outGBuffer2);
}
inline half4 LightingBlinnPhong_Deferred(SurfaceOutput s, half3 viewDir, UnityGI gi, out half4 outGBuffer0, out half4 outGBuffer1, out half4 outGBuffer2) {
    return VarcLegacyDeferred(s, gi, _SpecColor.rgb * s.Gloss, s.Specular, outGBuffer0, outGBuffer1, outGBuffer2);
}

// Legacy deferred lighting (the light pre-pass of Unity 4/5): |light| is the accumulated light,
// rgb diffuse and a the specular term. Lambert: albedo * light.rgb. Blinn-Phong adds the
// specular light.rgb * _SpecColor * (light.a * Gloss); alpha s.Alpha + spec * _SpecColor.a.
inline fixed4 LightingLambert_PrePass(SurfaceOutput s, half4 light) {
    fixed4 c;
    c.rgb = s.Albedo * light.rgb;
    c.a = s.Alpha;
    return c;
}
inline fixed4 LightingBlinnPhong_PrePass(SurfaceOutput s, half4 light) {
    fixed spec = light.a * s.Gloss;
    fixed4 c;
    c.rgb = s.Albedo * light.rgb + light.rgb * _SpecColor.rgb * spec;
    c.a = s.Alpha + spec * _SpecColor.a;
    return c;
}

// Unity 4's directional lightmaps: three lightmaps along the radiosity-normal-mapping basis
// (three unit vectors 120 degrees apart around +z, tilted 54.7 degrees from it).
#define UNITY_DIRBASIS \
    const half3x3 unity_DirBasis = half3x3( \
        half3(0.81649658, 0.0, 0.57735027), \
        half3(-0.40824830, 0.70710678, 0.57735027), \
        half3(-0.40824830, -0.70710678, 0.57735027));
// The lightmap colour (decoded) weighted by how much the normal faces each basis vector:
// scalePerBasisVector = the decoded scale texel, one weight per basis vector; with a normal
// written by the surface function the colour is scaled by dot(saturate(dirBasis * normal),
// scalePerBasisVector), else left as it is.
inline half3 DirLightmapDiffuse(in half3x3 dirBasis, fixed4 color, fixed4 scale, half3 normal, bool surfFuncWritesNormal, out half3 scalePerBasisVector) {
    half3 lm = DecodeLightmap(color);
    scalePerBasisVector = DecodeLightmap(scale);
    if (surfFuncWritesNormal) {
        half3 normalInRnmBasis = saturate(mul(dirBasis, normal));
        lm *= dot(normalInRnmBasis, scalePerBasisVector);
    }
    return lm;
}

#endif // LIGHTING_INCLUDED
