// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityStandardUtils.cginc. Material helpers of the Standard shader family:
// metallic/specular workflow conversion, energy conservation, SH evaluation per pixel, normal
// unpacking. Formulas are stated at each function and in docs/LIGHTING.md. Written for varc.
#ifndef UNITY_STANDARD_UTILS_INCLUDED
#define UNITY_STANDARD_UTILS_INCLUDED

#include "UnityCG.cginc"

// Reflectivity of a specular colour: its largest component (docs/LIGHTING.md §1).
half SpecularStrength(half3 specular) {
    return max(max(specular.r, specular.g), specular.b);
}

// Specular workflow: diffuse = albedo * (1 - SpecularStrength(specColor)).
inline half3 EnergyConservationBetweenDiffuseAndSpecular(half3 albedo, half3 specColor, out half oneMinusReflectivity) {
    oneMinusReflectivity = 1 - SpecularStrength(specColor);
    return albedo * oneMinusReflectivity;
}

// Metallic workflow (docs/LIGHTING.md §1): F0_dielectric = 0.04,
// oneMinusReflectivity = (1 - 0.04) * (1 - metallic), specColor = lerp(0.04, albedo, metallic),
// diffuse = albedo * oneMinusReflectivity.
inline half OneMinusReflectivityFromMetallic(half metallic) {
    half oneMinusDielectricSpec = unity_ColorSpaceDielectricSpec.a;
    return oneMinusDielectricSpec - metallic * oneMinusDielectricSpec;
}
inline half3 DiffuseAndSpecularFromMetallic(half3 albedo, half metallic, out half3 specColor, out half oneMinusReflectivity) {
    specColor = lerp(unity_ColorSpaceDielectricSpec.rgb, albedo, metallic);
    oneMinusReflectivity = OneMinusReflectivityFromMetallic(metallic);
    return albedo * oneMinusReflectivity;
}

// Transparent materials: diffuse *= alpha; outAlpha = 1 - oneMinusReflectivity + alpha * oneMinusReflectivity.
inline half3 PreMultiplyAlpha(half3 diffColor, half alpha, half oneMinusReflectivity, out half outModifiedAlpha) {
    outModifiedAlpha = 1 - oneMinusReflectivity + alpha * oneMinusReflectivity;
    return diffColor * alpha;
}

// Light-probe SH: varc evaluates the full L0-L2 polynomial per pixel; the per-vertex part
// passes the ambient through (UNITY_SAMPLE_FULL_SH_PER_PIXEL behaviour). §5.3.
half3 ShadeSHPerVertex(half3 normal, half3 ambient) { return ambient; }
half3 ShadeSHPerPixel(half3 normal, half3 ambient, float3 worldPos) {
    return ambient + max(half3(0, 0, 0), ShadeSH9(half4(normal, 1.0)));
}

// Tangent-space normal from a plain-RGB normal map, xy scaled by bumpScale.
half3 UnpackScaleNormal(half4 packednormal, half bumpScale) {
    half3 normal = packednormal.xyz * 2 - 1;
    normal.xy *= bumpScale;
    return normal;
}
// Whiteout blend of two tangent-space normals.
half3 BlendNormals(half3 n1, half3 n2) {
    return normalize(half3(n1.xy + n2.xy, n1.z * n2.z));
}

#endif // UNITY_STANDARD_UTILS_INCLUDED
