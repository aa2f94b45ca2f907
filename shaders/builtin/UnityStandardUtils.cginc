// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityStandardUtils.cginc. Material helpers of the Standard shader family:
// metallic/specular workflow conversion, energy conservation, SH evaluation per pixel, normal
// unpacking. Formulas are stated at each function and in docs/LIGHTING.md. Written for varc.
#ifndef UNITY_STANDARD_UTILS_INCLUDED
#define UNITY_STANDARD_UTILS_INCLUDED

#include "UnityCG.cginc"
#include "UnityStandardConfig.cginc"

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

// The Transparent mode (_ALPHAPREMULTIPLY_ON, blended One OneMinusSrcAlpha): diffuse *= alpha,
// and the reflective part stays opaque: outAlpha = 1 - oneMinusReflectivity + alpha *
// oneMinusReflectivity. Any other mode (Fade blends by alpha itself): both unchanged.
inline half3 PreMultiplyAlpha(half3 diffColor, half alpha, half oneMinusReflectivity, out half outModifiedAlpha) {
#if defined(_ALPHAPREMULTIPLY_ON)
    outModifiedAlpha = 1 - oneMinusReflectivity + alpha * oneMinusReflectivity;
    return diffColor * alpha;
#else
    outModifiedAlpha = alpha;
    return diffColor;
#endif
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

// ---------------------------------------------------------------------------------------------
// Additions for third-party shaders.
// ---------------------------------------------------------------------------------------------
// Box-projected reflection lookup: the reflected ray from worldPos is intersected with the
// probe's axis-aligned box [boxMin, boxMax] and the lookup direction becomes (hit - centre).
// cubemapCenter.w <= 0 (an infinitely distant probe) leaves the direction unchanged.
inline float3 BoxProjectedCubemapDirection(float3 worldRefl, float3 worldPos, float4 cubemapCenter, float4 boxMin, float4 boxMax) {
    UNITY_BRANCH
    if (cubemapCenter.w > 0.0) {
        float3 dir = normalize(worldRefl);
        float3 tMax = (boxMax.xyz - worldPos) / dir;
        float3 tMin = (boxMin.xyz - worldPos) / dir;
        float3 tExit = float3(dir.x > 0.0 ? tMax.x : tMin.x, dir.y > 0.0 ? tMax.y : tMin.y, dir.z > 0.0 ? tMax.z : tMin.z);
        float t = min(min(tExit.x, tExit.y), tExit.z);
        worldRefl = (worldPos - cubemapCenter.xyz) + dir * t;
    }
    return worldRefl;
}

// Normal maps are plain RGB in varc, so the RG/AG variant is UnpackScaleNormal.
half3 UnpackScaleNormalRGorAG(half4 packednormal, half bumpScale) { return UnpackScaleNormal(packednormal, bumpScale); }

// lerp(1, b, t) for colours and scalars (occlusion and detail strength of the Standard shader).
inline half3 LerpWhiteTo(half3 b, half t) { return half3(1.0 - t, 1.0 - t, 1.0 - t) + b * t; }
inline half LerpOneTo(half b, half t) { return (1.0 - t) + b * t; }

// HLSL truncates a vector argument to a scalar parameter; glslang does not. Some shaders pass a
// float3 metallic (all components equal): these overloads take its first component.
inline half3 DiffuseAndSpecularFromMetallic(half3 albedo, half3 metallic, out half3 specColor, out half oneMinusReflectivity) {
    return DiffuseAndSpecularFromMetallic(albedo, metallic.x, specColor, oneMinusReflectivity);
}
inline half OneMinusReflectivityFromMetallic(half3 metallic) { return OneMinusReflectivityFromMetallic(metallic.x); }

// Single-step parallax offset: the height h (0..1) is centred on the surface (h * height -
// height / 2) and moved along the tangent-space view direction, whose z is biased by 0.42 to
// limit the shift at grazing angles.
inline float2 ParallaxOffset1Step(half h, half height, half3 viewDir) {
    h = h * height - height / 2.0;
    half3 v = normalize(viewDir);
    v.z += 0.42;
    return h * (v.xy / v.z);
}

// ---------------------------------------------------------------------------------------------
// More normal helpers (issue #27).
// ---------------------------------------------------------------------------------------------
// Two-channel (DXT5nm: x in alpha, y in green) normal with xy scaled by bumpScale, z rebuilt.
half3 UnpackScaleNormalDXT5nm(half4 packednormal, half bumpScale) {
    half3 normal;
    normal.xy = (packednormal.wy * 2 - 1) * bumpScale;
    normal.z = sqrt(1.0 - saturate(dot(normal.xy, normal.xy)));
    return normal;
}

// Rows tangent, binormal, normal of the tangent-to-world rotation; the binormal's sign is the
// tangent's w times unity_WorldTransformParams.w (negative for mirroring transforms).
half3x3 CreateTangentToWorldPerVertex(half3 normal, half3 tangent, half tangentSign) {
    half sign = tangentSign * unity_WorldTransformParams.w;
    half3 binormal = cross(normal, tangent) * sign;
    return half3x3(tangent, binormal, normal);
}

// Bump mapping without tangents (surface gradients, M. Mikkelsen, "Bump Mapping Unparametrized
// Surfaces on the GPU", 2010): the height's screen-space derivatives dhdx, dhdy and the
// position's dpdx, dpdy give the surface gradient; the perturbed normal is n minus it.
half3 CalculateSurfaceGradient(half3 n, half3 dpdx, half3 dpdy, half dhdx, half dhdy) {
    half3 r1 = cross(dpdy, n);
    half3 r2 = cross(n, dpdx);
    return (r1 * dhdx + r2 * dhdy) / dot(dpdx, r1);
}
half3 PerturbNormal(half3 n, half3 dpdx, half3 dpdy, half dhdx, half dhdy) {
    return normalize(n - CalculateSurfaceGradient(n, dpdx, dpdy, dhdx, dhdy));
}
// The same from a height gradient in uv space (fragment stage: screen-space derivatives).
half3 CalculateSurfaceNormal(half3 position, half3 normal, half2 gradient, half2 uv) {
    half3 dpdx = ddx(position);
    half3 dpdy = ddy(position);
    half dhdx = dot(gradient, ddx(uv));
    half dhdy = dot(gradient, ddy(uv));
    return PerturbNormal(normal, dpdx, dpdy, dhdx, dhdy);
}

#endif // UNITY_STANDARD_UTILS_INCLUDED
