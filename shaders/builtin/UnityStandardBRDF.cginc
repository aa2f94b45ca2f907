// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityStandardBRDF.cginc. varc's physically based BRDF behind UNITY_BRDF_PBS:
// GGX (Trowbridge-Reitz) distribution, height-correlated Smith-GGX visibility (approximation),
// Schlick Fresnel, Burley ("Disney") diffuse; Unity's input contract (diffColor, specColor,
// oneMinusReflectivity, smoothness, normal, viewDir, UnityLight, UnityIndirect). The exact
// formula, for CPU re-implementation, is docs/LIGHTING.md §2. Written for varc.
#ifndef UNITY_STANDARD_BRDF_INCLUDED
#define UNITY_STANDARD_BRDF_INCLUDED

#include "UnityCG.cginc"
#include "UnityStandardConfig.cginc"
#include "UnityStandardUtils.cginc"
#include "UnityLightingCommon.cginc"

// ---------------------------------------------------------------------------------------------
// Small helpers (docs/LIGHTING.md §2).
// ---------------------------------------------------------------------------------------------
inline half Pow4(half x) { return x * x * x * x; }
inline half Pow5(half x) { return x * x * x * x * x; }
inline float2 Pow4(float2 x) { return x * x * x * x; }
inline half3 Pow4(half3 x) { return x * x * x * x; }
inline half4 Pow4(half4 x) { return x * x * x * x; }
inline half2 Pow5(half2 x) { return x * x * x * x * x; }
inline half3 Pow5(half3 x) { return x * x * x * x * x; }
inline half4 Pow5(half4 x) { return x * x * x * x * x; }
// x / |x|, with |x|^2 clamped to >= 0.001 so a zero vector stays finite.
inline float3 Unity_SafeNormalize(float3 inVec) {
    float dp3 = max(0.001f, dot(inVec, inVec));
    return inVec * rsqrt(dp3);
}
// Smoothness s -> perceptual roughness 1 - s -> roughness alpha = (1 - s)^2.
inline float SmoothnessToPerceptualRoughness(float smoothness) { return (1 - smoothness); }
inline float PerceptualRoughnessToRoughness(float perceptualRoughness) { return perceptualRoughness * perceptualRoughness; }
inline half RoughnessToPerceptualRoughness(half roughness) { return sqrt(roughness); }
inline half SmoothnessToRoughness(half smoothness) { return (1 - smoothness) * (1 - smoothness); }

// DotClamped, LambertTerm, BlinnTerm and the 5.x BRDF terms (UnityDeprecated.cginc).
#define INCLUDE_UNITY_STANDARD_BRDF_DEPRECATED
#include "UnityDeprecated.cginc"
#undef INCLUDE_UNITY_STANDARD_BRDF_DEPRECATED

// Schlick 1994: F(cos) = F0 + (1 - F0)(1 - cos)^5.
inline half3 FresnelTerm(half3 F0, half cosA) {
    half t = Pow5(1 - cosA);
    return F0 + (1 - F0) * t;
}
inline half3 FresnelLerp(half3 F0, half3 F90, half cosA) {
    half t = Pow5(1 - cosA);
    return lerp(F0, F90, t);
}

// Burley 2012 diffuse, without the 1/pi (varc's light units, docs/LIGHTING.md §2):
// Fd90 = 0.5 + 2 LdotH^2 rho; Fd = (1 + (Fd90-1)(1-NdotL)^5)(1 + (Fd90-1)(1-NdotV)^5).
half DisneyDiffuse(half NdotV, half NdotL, half LdotH, half perceptualRoughness) {
    half fd90 = 0.5 + 2 * LdotH * LdotH * perceptualRoughness;
    half lightScatter = (1 + (fd90 - 1) * Pow5(1 - NdotL));
    half viewScatter = (1 + (fd90 - 1) * Pow5(1 - NdotV));
    return lightScatter * viewScatter;
}

// Height-correlated Smith-GGX visibility V = G / (4 NdotL NdotV), Hammon 2017 approximation:
// V = 0.5 / (NdotL (NdotV (1-a) + a) + NdotV (NdotL (1-a) + a) + 1e-5).
inline float SmithJointGGXVisibilityTerm(float NdotL, float NdotV, float roughness) {
    float a = roughness;
    float lambdaV = NdotL * (NdotV * (1 - a) + a);
    float lambdaL = NdotV * (NdotL * (1 - a) + a);
    return 0.5f / (lambdaV + lambdaL + 1e-5f);
}

// GGX / Trowbridge-Reitz (Walter et al. 2007): D = a^2 / (pi ((NdotH^2)(a^2 - 1) + 1)^2).
inline float GGXTerm(float NdotH, float roughness) {
    float a2 = roughness * roughness;
    float d = (NdotH * a2 - NdotH) * NdotH + 1.0f;
    return UNITY_INV_PI * a2 / (d * d + 1e-7f);
}

// ---------------------------------------------------------------------------------------------
// The BRDF (docs/LIGHTING.md §2). Returns (rgb, 1).
// ---------------------------------------------------------------------------------------------
// Older BRDF terms (issue #27) some custom lighting functions call, with their textbook meaning.
// Schlick's Smith visibility 1 / (G1(NdotL) * G1(NdotV)), G1(x) = x (1 - k) + k, without the
// 1/4 (1e-5 keeps the grazing limit finite).
inline half SmithVisibilityTerm(half NdotL, half NdotV, half k) {
    half gL = NdotL * (1 - k) + k;
    half gV = NdotV * (1 - k) + k;
    return 1.0 / (gL * gV + 1e-5f);
}
// The same for a Beckmann distribution: k = roughness * sqrt(2 / pi), and the 1/4 included.
inline half SmithBeckmannVisibilityTerm(half NdotL, half NdotV, half roughness) {
    return SmithVisibilityTerm(NdotL, NdotV, roughness * 0.797884560802865) * 0.25;
}
// Energy-normalised Blinn-Phong lobe: (n + 2) / (2 pi) * NdotH^n.
inline half NDFBlinnPhongNormalizedTerm(half NdotH, half n) {
    return (n + 2.0) * (0.5 / UNITY_PI) * pow(NdotH, n);
}
// The Blinn-Phong exponent equivalent to a roughness: n = 2 / roughness^2 - 2 (both >= 1e-4).
inline half PerceptualRoughnessToSpecPower(half perceptualRoughness) {
    half m = PerceptualRoughnessToRoughness(perceptualRoughness);
    half sq = max(1e-4f, m * m);
    return max(2.0 / sq - 2.0, 1e-4f);
}
// A cheaper Fresnel blend: the fourth power of (1 - cosA) instead of Schlick's fifth.
inline half3 FresnelLerpFast(half3 F0, half3 F90, half cosA) { return lerp(F0, F90, Pow4(1 - cosA)); }

half4 BRDF1_Unity_PBS(half3 diffColor, half3 specColor, half oneMinusReflectivity, half smoothness,
                      float3 normal, float3 viewDir, UnityLight light, UnityIndirect gi)
{
    float perceptualRoughness = SmoothnessToPerceptualRoughness(smoothness);
    float roughness = max(PerceptualRoughnessToRoughness(perceptualRoughness), 0.002);
    float3 halfDir = Unity_SafeNormalize(float3(light.dir) + viewDir);

    half nv = saturate(abs(dot(normal, viewDir)));
    float nl = saturate(dot(normal, light.dir));
    float nh = saturate(dot(normal, halfDir));
    half lh = saturate(dot(light.dir, halfDir));

    half diffuseTerm = DisneyDiffuse(nv, nl, lh, perceptualRoughness) * nl;

    float V = SmithJointGGXVisibilityTerm(nl, nv, roughness);
    float D = GGXTerm(nh, roughness);
    float specularTerm = V * D * UNITY_PI;            // pi: diffuse carries no 1/pi
    specularTerm = max(0, specularTerm * nl);
    specularTerm *= any(specColor) ? 1.0 : 0.0;       // specColor = 0 disables specular exactly

    half surfaceReduction = 1.0 / (roughness * roughness + 1.0);
    half grazingTerm = saturate(smoothness + (1 - oneMinusReflectivity));

    half3 color = diffColor * (gi.diffuse + light.color * diffuseTerm)
                + specularTerm * light.color * FresnelTerm(specColor, lh)
                + surfaceReduction * gi.specular * FresnelLerp(specColor, grazingTerm, nv);
    return half4(color, 1);
}

// BRDF1 takes |N.V| for back-facing view directions (Unity's switch; 1 would clamp instead).
#define UNITY_HANDLE_CORRECTLY_NEGATIVE_NDOTV 0

// The cheaper tiers Unity picks for lower shader targets (UNITY_PBS_USE_BRDF2 / _BRDF3), in
// varc's units (diffuse without 1/pi, specular times pi, docs/LIGHTING.md §2).
// BRDF2: GGX with visibility and Fresnel folded into one term (the "optimised mobile GGX" of
// SIGGRAPH 2015): spec = a^2 / (4 d^2 max(0.1, LdotH^2) (a + 0.5)), d = NdotH^2 (a^2 - 1) + 1,
// a = (1 - smoothness)^2, clamped to [0, 100]; indirect specular faded by
// 1 - a * perceptualRoughness * (0.6 - 0.08 perceptualRoughness) towards the grazing colour
// with the fourth-power Fresnel.
half4 BRDF2_Unity_PBS(half3 diffColor, half3 specColor, half oneMinusReflectivity, half smoothness,
                      float3 normal, float3 viewDir, UnityLight light, UnityIndirect gi)
{
    float3 halfDir = Unity_SafeNormalize(float3(light.dir) + viewDir);
    half nl = saturate(dot(normal, light.dir));
    float nh = saturate(dot(normal, halfDir));
    half nv = saturate(dot(normal, viewDir));
    float lh = saturate(dot(light.dir, halfDir));
    half perceptualRoughness = SmoothnessToPerceptualRoughness(smoothness);
    half roughness = PerceptualRoughnessToRoughness(perceptualRoughness);
    float a2 = roughness * roughness;
    float d = nh * nh * (a2 - 1.0f) + 1.00001f;
    float specularTerm = a2 / (max(0.1f, lh * lh) * (roughness + 0.5f) * (d * d) * 4.0f);
    specularTerm = clamp(specularTerm, 0.0, 100.0);
#if defined(_SPECULARHIGHLIGHTS_OFF)
    specularTerm = 0.0;
#endif
    half surfaceReduction = 1.0 - roughness * perceptualRoughness * (0.6 - 0.08 * perceptualRoughness);
    half grazingTerm = saturate(smoothness + (1 - oneMinusReflectivity));
    half3 color = (diffColor + specularTerm * specColor) * light.color * nl
                + gi.diffuse * diffColor
                + surfaceReduction * gi.specular * FresnelLerpFast(specColor, grazingTerm, nv);
    return half4(color, 1);
}

// BRDF3 direct part: diffuse plus a normalised Phong lobe on the mirror direction,
// (n + 2) / 2 * RdotL^n with RdotL^n = rlPow4^(n / 4) and n = 2 / a^2 - 2 (a = (1 - s)^2,
// clamped to [1e-4, 10000]). Unity reads the lobe from the lookup texture unity_NHxRoughness;
// varc evaluates it (the texture is declared for shaders that sample it themselves).
half3 BRDF3_Direct(half3 diffColor, half3 specColor, half rlPow4, half smoothness) {
    half r = 1 - smoothness;
    half a = r * r;
    half n = clamp(2.0 / max(a * a, 1e-4) - 2.0, 1e-4, 10000.0);
    half specular = (n + 2.0) * 0.5 * pow(max(rlPow4, 0.0), n * 0.25);
#if defined(_SPECULARHIGHLIGHTS_OFF)
    specular = 0.0;
#endif
    return diffColor + specular * specColor;
}
// BRDF3 indirect part: diffuse GI times albedo, and the environment towards the grazing colour
// by fresnelTerm.
half3 BRDF3_Indirect(half3 diffColor, half3 specColor, UnityIndirect indirect, half grazingTerm, half fresnelTerm) {
    half3 c = indirect.diffuse * diffColor;
#if !defined(_GLOSSYREFLECTIONS_OFF)
    c += indirect.specular * lerp(specColor, grazingTerm, fresnelTerm);
#endif
    return c;
}
// BRDF3: R = reflect(-viewDir, normal); rlPow4 = max(0, R.L)^4, fresnelTerm = (1 - NdotV)^4.
half4 BRDF3_Unity_PBS(half3 diffColor, half3 specColor, half oneMinusReflectivity, half smoothness,
                      float3 normal, float3 viewDir, UnityLight light, UnityIndirect gi)
{
    float3 reflDir = reflect(-viewDir, normal);
    half nl = saturate(dot(normal, light.dir));
    half nv = saturate(dot(normal, viewDir));
    half rlPow4 = Pow4(max(0.0, (half)dot(reflDir, light.dir)));
    half fresnelTerm = Pow4(1 - nv);
    half grazingTerm = saturate(smoothness + (1 - oneMinusReflectivity));
    half3 color = BRDF3_Direct(diffColor, specColor, rlPow4, smoothness) * light.color * nl;
    color += BRDF3_Indirect(diffColor, specColor, gi, grazingTerm, fresnelTerm);
    return half4(color, 1);
}
#if defined(SHADER_API_MOBILE)
sampler2D unity_NHxRoughness;
#else
sampler2D_float unity_NHxRoughness;
#endif

#endif // UNITY_STANDARD_BRDF_INCLUDED
