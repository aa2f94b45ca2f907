// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityDeprecated.cginc. Lighting helpers Unity kept for shaders written against
// older releases: the legacy light-correction constants, the BRDF terms of the 5.x Standard
// shader (defined when UnityStandardBRDF.cginc includes this file with
// INCLUDE_UNITY_STANDARD_BRDF_DEPRECATED) and the old Unity_GlossyEnvironment overload (defined
// when UnityImageBasedLighting.cginc includes it with INCLUDE_UNITY_IMAGE_BASED_LIGHTING_DEPRECATED).
// Each part has its own guard because the file is included once per part. Written for varc from
// the cited formulas; not derived from Unity's file.
//
// Visibility terms follow the 5.x convention: V = G / (NdotL NdotV), without the 1/4 of the
// microfacet denominator (the caller multiplies by unity_LightGammaCorrectionConsts_PIDiv4 with
// a distribution that includes 1/pi).

#ifndef UNITY_DEPRECATED_INCLUDED
#define UNITY_DEPRECATED_INCLUDED

// Light-correction constants: pi/4, 1/(2 pi), 8 and sqrt(2/pi) in linear space; their squares in
// gamma space, where light colours are squared relative to linear (gamma ~2).
#ifdef UNITY_COLORSPACE_GAMMA
#define unity_LightGammaCorrectionConsts_PIDiv4 (0.61685027507f)
#define unity_LightGammaCorrectionConsts_HalfDivPI (0.02533029591f)
#define unity_LightGammaCorrectionConsts_8 (64.0f)
#define unity_LightGammaCorrectionConsts_SqrtHalfPI (0.63661977236f)
#else
#define unity_LightGammaCorrectionConsts_PIDiv4 (0.78539816340f)
#define unity_LightGammaCorrectionConsts_HalfDivPI (0.15915494309f)
#define unity_LightGammaCorrectionConsts_8 (8.0f)
#define unity_LightGammaCorrectionConsts_SqrtHalfPI (0.79788456080f)
#endif

#endif // UNITY_DEPRECATED_INCLUDED

#if defined(INCLUDE_UNITY_STANDARD_BRDF_DEPRECATED) && !defined(UNITY_DEPRECATED_BRDF_INCLUDED)
#define UNITY_DEPRECATED_BRDF_INCLUDED

inline half DotClamped(half3 a, half3 b) { return max(0.0h, dot(a, b)); }
inline half LambertTerm(half3 normal, half3 lightDir) { return DotClamped(normal, lightDir); }
inline half BlinnTerm(half3 normal, half3 halfDir) { return DotClamped(normal, halfDir); }

// Blinn-Phong exponent of the GGX lobe of perceptual roughness r (Walter et al. 2007):
// alpha = r^2, n = 2 / alpha^2 - 2, both clamped to >= 1e-4.
inline half RoughnessToSpecPower(half roughness) {
    half alpha = roughness * roughness;
    half n = 2.0 / max(alpha * alpha, 1e-4) - 2.0;
    return max(n, 1e-4);
}

// Normalised Blinn-Phong distribution: (n + 2) / (2 pi) NdotH^n.
inline half RDFBlinnPhongNormalizedTerm(half NdotH, half n) {
    return (n + 2.0) * 0.15915494309 * pow(NdotH, n);
}

// The shadowing term G cancels the microfacet denominator exactly.
inline half ImplicitVisibilityTerm() { return 1; }

// Smith with Schlick's approximation for GGX, k = alpha / 2 (alpha = perceptual roughness^2):
// 1 / ((NdotL (1 - k) + k) (NdotV (1 - k) + k)).
inline half SmithGGXVisibilityTerm(half NdotL, half NdotV, half perceptualRoughness) {
    half k = perceptualRoughness * perceptualRoughness * 0.5;
    half gL = NdotL * (1 - k) + k;
    half gV = NdotV * (1 - k) + k;
    return 1.0 / (gL * gV + 1e-5);
}

// Cook-Torrance 1982: G = min(1, 2 NdotH NdotV / VdotH, 2 NdotH NdotL / VdotH).
inline half CookTorranceVisibilityTerm(half NdotL, half NdotV, half NdotH, half VdotH) {
    VdotH = max(VdotH, 1e-4);
    half g = min(1.0, min(2.0 * NdotH * NdotV / VdotH, 2.0 * NdotH * NdotL / VdotH));
    return g / (NdotL * NdotV + 1e-4);
}

// Kelemen and Szirmay-Kalos 2001: G / (NdotL NdotV) ~ 1 / LdotH^2.
inline half KelemenVisibilityTerm(half LdotH) { return 1.0 / (LdotH * LdotH + 1e-5); }

// Kelemen's form with Schlick's roughness: k = alpha sqrt(2/pi), 1 / (LdotH (1 - k) + k)^2.
inline half ModifiedKelemenVisibilityTerm(half LdotH, half perceptualRoughness) {
    half k = perceptualRoughness * perceptualRoughness * 0.79788456080;
    half g = LdotH * (1 - k) + k;
    return 1.0 / (g * g + 1e-5);
}

// Lagarde 2011, Fresnel with roughness: F0 + (max(1 - roughness, F0) - F0) (1 - cosA)^5.
inline half3 SebLagardeFresnelTerm(half3 F0, half roughness, half cosA) {
    half t = 1 - cosA;
    t = t * t * t * t * t;
    return F0 + (max(1 - roughness, F0) - F0) * t;
}

// Lazarov 2013: Schlick's (1 - cosA)^5 divided by 4 - 3 gloss (gloss = 1 - roughness), so rough
// surfaces keep a quarter of the grazing Fresnel: F0 + (1 - F0) t / (1 + 3 roughness).
inline half3 LazarovFresnelTerm(half3 F0, half roughness, half cosA) {
    half t = 1 - cosA;
    t = t * t * t * t * t;
    t /= 4 - 3 * (1 - roughness);
    return F0 + (1 - F0) * t;
}

// Shader model 2 had no linear-space HDR decode; every Vulkan target has, so this is DecodeHDR.
inline half3 DecodeHDR_NoLinearSupportInSM2(half4 data, half4 decodeInstructions) {
    return DecodeHDR(data, decodeInstructions);
}

#endif // INCLUDE_UNITY_STANDARD_BRDF_DEPRECATED

#if defined(INCLUDE_UNITY_IMAGE_BASED_LIGHTING_DEPRECATED) && !defined(UNITY_DEPRECATED_IBL_INCLUDED)
#define UNITY_DEPRECATED_IBL_INCLUDED

// The 5.x overload: the lookup direction and perceptual roughness passed directly.
half3 Unity_GlossyEnvironment(UNITY_ARGS_TEXCUBE(tex), half4 hdr, half3 worldNormal, half perceptualRoughness) {
    Unity_GlossyEnvironmentData glossIn;
    glossIn.roughness = perceptualRoughness;
    glossIn.reflUVW = worldNormal;
    return Unity_GlossyEnvironment(UNITY_PASS_TEXCUBE(tex), hdr, glossIn);
}

#endif // INCLUDE_UNITY_IMAGE_BASED_LIGHTING_DEPRECATED
