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

#endif // LIGHTING_INCLUDED
