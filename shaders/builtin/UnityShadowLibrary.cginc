// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityShadowLibrary.cginc. Real-time shadow-map sampling for spot (SHADOWS_DEPTH)
// and point (SHADOWS_CUBE) lights, soft filtering (SHADOWS_SOFT), and the shadow-distance fade.
// Conventions (depth ranges, texture contents): docs/SHADER_ABI.md §4.7 and §6; the exact
// formulas: docs/LIGHTING.md §6. Keywords: docs/KEYWORDS.md §9. Written for varc.
#ifndef UNITY_BUILTIN_SHADOW_LIBRARY_INCLUDED
#define UNITY_BUILTIN_SHADOW_LIBRARY_INCLUDED

#include "HLSLSupport.cginc"
#include "UnityShaderVariables.cginc"

// ---------------------------------------------------------------------------------------------
// Tent filters (soft shadows): a tent of half-width h and unit area centred on the shadow
// coordinate; each shadow-map texel is weighted by the tent's area over it. 3 texels wide for spot
// lights, 7 for the directional collector (what Unity's bilinear-compare taps add up to).
// ---------------------------------------------------------------------------------------------
inline float UnityShadowTentArea(float x, float h) {  // the tent's area left of x
    float t = saturate((x + h) / h);
    float u = saturate((h - x) / h);
    return x <= 0.0 ? 0.5 * t * t : 1.0 - 0.5 * u * u;
}

// ---------------------------------------------------------------------------------------------
// Spot-light shadows: a depth map rendered with unity_WorldToShadow[0]; 1 = lit.
// SHADOWS_SCREEN programs declare their own _ShadowMapTexture (AutoLight.cginc or the shader).
// ---------------------------------------------------------------------------------------------
#if defined(SHADOWS_DEPTH) && !defined(SHADOWS_SCREEN)
// A program that declared the map itself says so with SHADOWMAPSAMPLER_DEFINED.
#if !defined(SHADOWMAPSAMPLER_DEFINED)
UNITY_DECLARE_SHADOWMAP(_ShadowMapTexture);
#define SHADOWMAPSAMPLER_DEFINED
#endif
#if defined(SHADOWS_SOFT)
// The map and its _TexelSize (UnityShaderVariables.cginc) are both there for the PCF filters.
#define SHADOWMAPSAMPLER_AND_TEXELSIZE_DEFINED
#endif

// shadowCoord = mul(unity_WorldToShadow[0], float4(worldPos, 1)). Hard: one depth comparison at
// the nearest texel. Soft: the 3-texel tent over the 4 x 4 texels around the coordinate.
// Result lerp(1 - strength, 1, lit).
inline fixed UnitySampleShadowmap(float4 shadowCoord) {
    float3 coord = shadowCoord.xyz / shadowCoord.w;
#if defined(SHADOWS_SOFT)
    float2 position = coord.xy * _ShadowMapTexture_TexelSize.zw;
    float2 centre = floor(position + 0.5);
    float2 offset = position - centre;
    half lit = 0.0;
    for (int j = -2; j < 2; ++j) {
        float wy = UnityShadowTentArea(j + 1 - offset.y, 1.5)
                 - UnityShadowTentArea(j - offset.y, 1.5);
        for (int i = -2; i < 2; ++i) {
            float wx = UnityShadowTentArea(i + 1 - offset.x, 1.5)
                     - UnityShadowTentArea(i - offset.x, 1.5);
            float2 uv = (centre + float2(i, j) + 0.5) * _ShadowMapTexture_TexelSize.xy;
            lit += wx * wy * UNITY_SAMPLE_SHADOW(_ShadowMapTexture, float3(uv, coord.z));
        }
    }
#else
    half lit = UNITY_SAMPLE_SHADOW(_ShadowMapTexture, coord);
#endif
    return lerp(_LightShadowData.r, 1.0, lit);
}
#endif

// ---------------------------------------------------------------------------------------------
// Point-light shadows: a depth cube map (Vulkan's depth-cube path). vec = worldPos - lightPos;
// the receiver's depth is that of vec's largest component m in the face camera, after the
// depth bias: d = -x + y / ((max(1e-5, m - z)) * w) with (x, y, z, w) = _LightProjectionParams.
// Hard: lit when d <= the stored depth. Soft: the mean of four lookups at vec + (+-1/128) along
// (+,+,+) (-,-,+) (-,+,-) (+,-,-). Result lerp(1 - strength, 1, lit).
// ---------------------------------------------------------------------------------------------
#if defined(SHADOWS_CUBE)
UNITY_DECLARE_TEXCUBE_SHADOWMAP(_ShadowMapTexture);

inline float UnityCubeShadowDepth(float3 vec) {
    float3 absVec = abs(vec);
    float m = max(max(absVec.x, absVec.y), absVec.z);
    m = max(0.00001, m - _LightProjectionParams.z) * _LightProjectionParams.w;
    return -_LightProjectionParams.x + _LightProjectionParams.y / m;
}

inline half UnityCubeShadowTap(float3 vec, float depth) {
    return depth <= texCUBElod(_ShadowMapTexture, float4(vec, 0)).r ? 1.0 : 0.0;
}

// The depth stored in the cube along vec (the map's .r; varc's point-light maps are depth cubes).
inline float SampleCubeDistance(float3 vec) { return texCUBElod(_ShadowMapTexture, float4(vec, 0)).r; }

inline half UnitySampleShadowmap(float3 vec) {
    float depth = UnityCubeShadowDepth(vec);
#if defined(SHADOWS_SOFT)
    float z = 1.0 / 128.0;
    half lit = 0.25 * (UnityCubeShadowTap(vec + float3( z,  z,  z), depth)
                     + UnityCubeShadowTap(vec + float3(-z, -z,  z), depth)
                     + UnityCubeShadowTap(vec + float3(-z,  z, -z), depth)
                     + UnityCubeShadowTap(vec + float3( z, -z, -z), depth));
#else
    half lit = UnityCubeShadowTap(vec, depth);
#endif
    return lerp(_LightShadowData.r, 1.0, lit);
}
#endif

// Unity 4's soft-shadow tap offsets (four taps around the coordinate): varc's filters above do
// not read them and its runtime never sets them, so they are constant zeros (a uniform would
// change the globals of every soft-shadow program).
#if defined(SHADOWS_SOFT)
static const float4 _ShadowOffsets[4] = {float4(0, 0, 0, 0), float4(0, 0, 0, 0), float4(0, 0, 0, 0), float4(0, 0, 0, 0)};
#endif
// A screen-space shadow with lightmaps: the GI code mixes realtime and baked shadows.
#if defined(SHADOWS_SCREEN) && defined(LIGHTMAP_ON)
#define HANDLE_SHADOWS_BLENDING_IN_GI 1
#endif

// ---------------------------------------------------------------------------------------------
// Shadow-distance fade (seed 002, "Fading Shadows"): the fade metric is the distance to the
// fade sphere's centre (unity_ShadowFadeCenterAndType.w = 1) or the view depth (w = 0); the fade
// factor is saturate(dist * _LightShadowData.z + _LightShadowData.w), 0 = full shadow,
// 1 = shadow gone. Callers apply it as saturate(shadow + fade).
// ---------------------------------------------------------------------------------------------
float UnityComputeShadowFadeDistance(float3 wpos, float z) {
    float sphereDist = distance(wpos, unity_ShadowFadeCenterAndType.xyz);
    return lerp(z, sphereDist, unity_ShadowFadeCenterAndType.w);
}
half UnityComputeShadowFade(float fadeDist) {
    return saturate(fadeDist * _LightShadowData.z + _LightShadowData.w);
}

// ---------------------------------------------------------------------------------------------
// Realtime and baked shadows together (issue #27). realtimeShadowAttenuation: the realtime
// shadow (1 = lit); bakedShadowAttenuation: the baked shadow mask (1 = lit); fade: the distance
// fade above (0 = full realtime shadow, 1 = realtime shadow gone). Without a realtime shadow
// keyword only the baked shadow counts; with a shadow mask (SHADOWS_SHADOWMASK) the faded
// realtime shadow and the baked one are combined by min; otherwise (varc has no subtractive
// mixing) the realtime shadow fades out: saturate(realtime + fade).
// ---------------------------------------------------------------------------------------------
inline half UnityMixRealtimeAndBakedShadows(half realtimeShadowAttenuation, half bakedShadowAttenuation, half fade) {
#if !defined(SHADOWS_DEPTH) && !defined(SHADOWS_SCREEN) && !defined(SHADOWS_CUBE)
    return bakedShadowAttenuation;
#elif defined(SHADOWS_SHADOWMASK)
    return min(saturate(realtimeShadowAttenuation + fade), bakedShadowAttenuation);
#else
    return saturate(realtimeShadowAttenuation + fade);
#endif
}

// The PCF functions read _ShadowMapTexture and its _TexelSize: the spot-light map declared above,
// or one a shader (a screen-space shadow collector) declared itself before including this file,
// saying so with SHADOWMAPSAMPLER_AND_TEXELSIZE_DEFINED.
#if (defined(SHADOWS_DEPTH) && !defined(SHADOWS_SCREEN)) || defined(SHADOWMAPSAMPLER_AND_TEXELSIZE_DEFINED)
// Percentage-closer filtering of the spot-light map with a tent of width 2 * halfWidth texels
// (the area of the tent over each texel weights that texel's depth comparison); coord is the
// shadow coordinate (divided by w here). receiverPlaneDepthBias is accepted and not used: varc's
// casters carry the bias (unity_LightShadowBias). 1 = lit, before the shadow strength.
inline half VarcSampleShadowmapTent(float4 coord, float halfWidth, int radius) {
    float3 c = coord.xyz / coord.w;
    float2 position = c.xy * _ShadowMapTexture_TexelSize.zw;
    float2 centre = floor(position + 0.5);
    float2 offset = position - centre;
    half lit = 0.0;
    for (int j = -radius; j < radius; ++j) {
        float wy = UnityShadowTentArea(j + 1 - offset.y, halfWidth) - UnityShadowTentArea(j - offset.y, halfWidth);
        for (int i = -radius; i < radius; ++i) {
            float wx = UnityShadowTentArea(i + 1 - offset.x, halfWidth) - UnityShadowTentArea(i - offset.x, halfWidth);
            float2 uv = (centre + float2(i, j) + 0.5) * _ShadowMapTexture_TexelSize.xy;
            lit += wx * wy * UNITY_SAMPLE_SHADOW(_ShadowMapTexture, float3(uv, c.z));
        }
    }
    return lit;
}
inline half UnitySampleShadowmap_PCF3x3(float4 coord, float3 receiverPlaneDepthBias) { return VarcSampleShadowmapTent(coord, 1.5, 2); }
inline half UnitySampleShadowmap_PCF5x5(float4 coord, float3 receiverPlaneDepthBias) { return VarcSampleShadowmapTent(coord, 2.5, 3); }
inline half UnitySampleShadowmap_PCF7x7(float4 coord, float3 receiverPlaneDepthBias) { return VarcSampleShadowmapTent(coord, 3.5, 4); }
// The same tents under their explicit names, and the 3x3 filter of devices without compare
// samplers (varc compares in the shader everywhere).
inline half UnitySampleShadowmap_PCF3x3Tent(float4 coord, float3 receiverPlaneDepthBias) { return VarcSampleShadowmapTent(coord, 1.5, 2); }
inline half UnitySampleShadowmap_PCF5x5Tent(float4 coord, float3 receiverPlaneDepthBias) { return VarcSampleShadowmapTent(coord, 2.5, 3); }
inline half UnitySampleShadowmap_PCF7x7Tent(float4 coord, float3 receiverPlaneDepthBias) { return VarcSampleShadowmapTent(coord, 3.5, 4); }
inline half UnitySampleShadowmap_PCF3x3NoHardwareSupport(float4 coord, float3 receiverPlaneDepthBias) { return VarcSampleShadowmapTent(coord, 1.5, 2); }
// Gaussian filters: the binomial kernels (1 2 1)/4 and (1 4 6 4 1)/16, separable, over the
// texels centred on the one holding the coordinate. 1 = lit, before the shadow strength.
inline half VarcSampleShadowmapBinomial(float4 coord, int radius) {
    float3 c = coord.xyz / coord.w;
    float2 centre = floor(c.xy * _ShadowMapTexture_TexelSize.zw);
    float kernel[5] = {1.0, 4.0, 6.0, 4.0, 1.0};
    float norm = radius == 1 ? 16.0 : 256.0;
    half lit = 0.0;
    for (int j = -radius; j <= radius; ++j) {
        for (int i = -radius; i <= radius; ++i) {
            float w = radius == 1 ? (2.0 - abs(i)) * (2.0 - abs(j)) : kernel[i + 2] * kernel[j + 2];
            float2 uv = (centre + float2(i, j) + 0.5) * _ShadowMapTexture_TexelSize.xy;
            lit += w * UNITY_SAMPLE_SHADOW(_ShadowMapTexture, float3(uv, c.z));
        }
    }
    return lit / norm;
}
half UnitySampleShadowmap_PCF3x3Gaussian(float4 coord, float3 receiverPlaneDepthBias) { return VarcSampleShadowmapBinomial(coord, 1); }
half UnitySampleShadowmap_PCF5x5Gaussian(float4 coord, float3 receiverPlaneDepthBias) { return VarcSampleShadowmapBinomial(coord, 2); }
#endif

#include "VarcShadowTentWeights.cginc"

// Receiver-plane depth bias: varc's casters carry the bias (unity_LightShadowBias), so the
// receiver's plane adds none: (0, 0, 0). A shadow coordinate offset by deltaUV texels' uv then
// keeps the depth plus the plane's slope times the offset.
float3 UnityGetReceiverPlaneDepthBias(float3 shadowCoord, float biasMultiply) {
    return float3(0.0, 0.0, 0.0);
}
float3 UnityCombineShadowcoordComponents(float2 baseUV, float2 deltaUV, float depth, float3 receiverPlaneDepthBias) {
    return float3(baseUV + deltaUV, depth + dot(deltaUV, receiverPlaneDepthBias.xy));
}

// Baked shadow mask (LIGHTMAP_ON + SHADOWS_SHADOWMASK): all four channels, and this light's
// channel (unity_OcclusionMaskSelector); 1 when there is none. worldPos is for light probe
// proxy volumes, which varc does not have.
inline fixed4 UnityGetRawBakedOcclusions(float2 lightmapUV, float3 worldPos) {
#if defined(SHADOWS_SHADOWMASK) && defined(LIGHTMAP_ON)
    return UNITY_SAMPLE_TEX2D(unity_ShadowMask, lightmapUV);
#else
    return fixed4(1, 1, 1, 1);
#endif
}
// Without light probe proxy volumes (none in varc) a probe-lit object's occlusion is its probe's.
half4 LPPV_SampleProbeOcclusion(float3 worldPos) { return unity_ProbesOcclusion; }
inline fixed UnitySampleBakedOcclusion(float2 lightmapUV, float3 worldPos) {
#if defined(SHADOWS_SHADOWMASK) && defined(LIGHTMAP_ON)
    return saturate(dot(UNITY_SAMPLE_TEX2D(unity_ShadowMask, lightmapUV), unity_OcclusionMaskSelector));
#else
    return 1.0;
#endif
}

#endif // UNITY_BUILTIN_SHADOW_LIBRARY_INCLUDED
