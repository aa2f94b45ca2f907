// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityStandardInput.cginc. The material properties of Unity's Standard shader
// (declared in $Global, filled by name from the material) and the functions that read them:
// albedo with detail maps, alpha, occlusion, metallic/specular + smoothness, emission, tangent-
// space normal, parallax offset; plus the Standard vertex input. Keyword meanings follow the
// Standard shader (_NORMALMAP, _DETAIL_MULX2/_MUL/_ADD/_LERP, _METALLICGLOSSMAP,
// _SPECGLOSSMAP, _SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A, _EMISSION, _PARALLAXMAP). Written for varc
// from the documented behaviour; not derived from Unity's file.
#ifndef UNITY_STANDARD_INPUT_INCLUDED
#define UNITY_STANDARD_INPUT_INCLUDED

#include "UnityCG.cginc"
#include "UnityStandardConfig.cginc"
#include "UnityStandardUtils.cginc"
#include "UnityLightingCommon.cginc" // _SpecColor
#include "UnityPBSLighting.cginc"

// A tangent frame is interpolated when a normal map, a parallax map or directional lightmaps
// need it.
#if defined(_NORMALMAP) || defined(DIRLIGHTMAP_COMBINED) || defined(_PARALLAXMAP)
#define _TANGENT_TO_WORLD 1
#endif
// Unity 5.6 dropped samplers on D3D9 shader model 3 (16 samplers); Vulkan has no such limit.
#define EXCEEDS_D3D9_SM3_MAX_SAMPLER_COUNT 0
#if defined(_DETAIL_MULX2) || defined(_DETAIL_MUL) || defined(_DETAIL_ADD) || defined(_DETAIL_LERP)
#define _DETAIL 1
#endif

// ---------------------------------------------------------------------------------------------
// Material properties.
// ---------------------------------------------------------------------------------------------
half4 _Color;
half _Cutoff;
sampler2D _MainTex;
float4 _MainTex_ST;
sampler2D _DetailAlbedoMap;
float4 _DetailAlbedoMap_ST;
sampler2D _BumpMap;
half _BumpScale;
sampler2D _DetailMask;
sampler2D _DetailNormalMap;
half _DetailNormalMapScale;
sampler2D _SpecGlossMap;
sampler2D _MetallicGlossMap;
half _Metallic;
float _Glossiness;
float _GlossMapScale;
sampler2D _OcclusionMap;
half _OcclusionStrength;
sampler2D _ParallaxMap;
half _Parallax;
half _UVSec;           // 0: detail maps use uv0, 1: uv1
half4 _EmissionColor;
sampler2D _EmissionMap;

// ---------------------------------------------------------------------------------------------
// Vertex input of the Standard passes (named `v` by the vertex programs, as the AutoLight and
// shadow-caster macros expect).
// ---------------------------------------------------------------------------------------------
struct VertexInput {
    float4 vertex : POSITION;
    half3 normal : NORMAL;
    float2 uv0 : TEXCOORD0;
    float2 uv1 : TEXCOORD1;
#if defined(DYNAMICLIGHTMAP_ON) || defined(UNITY_PASS_META)
    float2 uv2 : TEXCOORD2;
#endif
#ifdef _TANGENT_TO_WORLD
    half4 tangent : TANGENT;
#endif
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

// xy = main uv (_MainTex_ST), zw = detail uv (_DetailAlbedoMap_ST on uv0 or uv1 per _UVSec).
float4 TexCoords(VertexInput v) {
    float4 texcoord;
    texcoord.xy = TRANSFORM_TEX(v.uv0, _MainTex);
    texcoord.zw = TRANSFORM_TEX(((_UVSec == 0) ? v.uv0 : v.uv1), _DetailAlbedoMap);
    return texcoord;
}

half DetailMask(float2 uv) { return tex2D(_DetailMask, uv).a; }

// _Color * _MainTex, then the detail albedo blended by the detail mask:
// MULX2: *= lerp(1, detail * 2 (linear: unity_ColorSpaceDouble), mask); MUL: *= lerp(1, detail, mask);
// ADD: += detail * mask; LERP: lerp(albedo, detail, mask).
half3 Albedo(float4 texcoords) {
    half3 albedo = _Color.rgb * tex2D(_MainTex, texcoords.xy).rgb;
#if defined(_DETAIL)
    half mask = DetailMask(texcoords.xy);
    half3 detailAlbedo = tex2D(_DetailAlbedoMap, texcoords.zw).rgb;
    #if defined(_DETAIL_MULX2)
        albedo *= LerpWhiteTo(detailAlbedo * unity_ColorSpaceDouble.rgb, mask);
    #elif defined(_DETAIL_MUL)
        albedo *= LerpWhiteTo(detailAlbedo, mask);
    #elif defined(_DETAIL_ADD)
        albedo += detailAlbedo * mask;
    #elif defined(_DETAIL_LERP)
        albedo = lerp(albedo, detailAlbedo, mask);
    #endif
#endif
    return albedo;
}

// Alpha = _MainTex.a * _Color.a, or _Color.a alone when the albedo alpha holds smoothness.
half Alpha(float2 uv) {
#if defined(_SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A)
    return _Color.a;
#else
    return tex2D(_MainTex, uv).a * _Color.a;
#endif
}

// Occlusion map .g, faded towards 1 by 1 - _OcclusionStrength.
half Occlusion(float2 uv) {
    return LerpOneTo(tex2D(_OcclusionMap, uv).g, _OcclusionStrength);
}

// Specular workflow: rgb = specular colour, a = smoothness.
half4 SpecularGloss(float2 uv) {
    half4 sg;
#ifdef _SPECGLOSSMAP
    #if defined(_SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A)
        sg.rgb = tex2D(_SpecGlossMap, uv).rgb;
        sg.a = tex2D(_MainTex, uv).a;
    #else
        sg = tex2D(_SpecGlossMap, uv);
    #endif
    sg.a *= _GlossMapScale;
#else
    sg.rgb = _SpecColor.rgb;
    #ifdef _SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A
        sg.a = tex2D(_MainTex, uv).a * _GlossMapScale;
    #else
        sg.a = _Glossiness;
    #endif
#endif
    return sg;
}

// Metallic workflow: x = metallic (map .r), y = smoothness (map .a or albedo .a, times _GlossMapScale).
half2 MetallicGloss(float2 uv) {
    half2 mg;
#ifdef _METALLICGLOSSMAP
    #ifdef _SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A
        mg.r = tex2D(_MetallicGlossMap, uv).r;
        mg.g = tex2D(_MainTex, uv).a;
    #else
        mg = tex2D(_MetallicGlossMap, uv).ra;
    #endif
    mg.g *= _GlossMapScale;
#else
    mg.r = _Metallic;
    #ifdef _SMOOTHNESS_TEXTURE_ALBEDO_CHANNEL_A
        mg.g = tex2D(_MainTex, uv).a * _GlossMapScale;
    #else
        mg.g = _Glossiness;
    #endif
#endif
    return mg;
}

// Roughness workflow: x = metallic (_MetallicGlossMap.r or _Metallic), y = smoothness =
// 1 - roughness (_SpecGlossMap.r or _Glossiness, which holds the roughness in this workflow).
half2 MetallicRough(float2 uv) {
    half2 mg;
#ifdef _METALLICGLOSSMAP
    mg.r = tex2D(_MetallicGlossMap, uv).r;
#else
    mg.r = _Metallic;
#endif
#ifdef _SPECGLOSSMAP
    mg.g = 1.0f - tex2D(_SpecGlossMap, uv).r;
#else
    mg.g = 1.0f - _Glossiness;
#endif
    return mg;
}

// Emission map * _EmissionColor (HDR, linear) when _EMISSION is on.
half3 Emission(float2 uv) {
#ifndef _EMISSION
    return 0;
#else
    return tex2D(_EmissionMap, uv).rgb * _EmissionColor.rgb;
#endif
}

#ifdef _NORMALMAP
// Tangent-space normal from _BumpMap (scaled by _BumpScale), with the detail normal map blended in
// by the detail mask.
half3 NormalInTangentSpace(float4 texcoords) {
    half3 normalTangent = UnpackScaleNormal(tex2D(_BumpMap, texcoords.xy), _BumpScale);
#if defined(_DETAIL) && UNITY_ENABLE_DETAIL_NORMALMAP
    half mask = DetailMask(texcoords.xy);
    half3 detailNormalTangent = UnpackScaleNormal(tex2D(_DetailNormalMap, texcoords.zw), _DetailNormalMapScale);
    #if defined(_DETAIL_LERP)
        normalTangent = lerp(normalTangent, detailNormalTangent, mask);
    #else
        normalTangent = lerp(normalTangent, BlendNormals(normalTangent, detailNormalTangent), mask);
    #endif
#endif
    return normalTangent;
}
#endif

// Parallax: shift both uv pairs by ParallaxOffset1Step(_ParallaxMap.g, _Parallax, tangent view dir).
float4 Parallax(float4 texcoords, half3 viewDir) {
#if !defined(_PARALLAXMAP)
    return texcoords;
#else
    half h = tex2D(_ParallaxMap, texcoords.xy).g;
    float2 offset = ParallaxOffset1Step(h, _Parallax, viewDir);
    return float4(texcoords.xy + offset, texcoords.zw + offset);
#endif
}

#endif // UNITY_STANDARD_INPUT_INCLUDED
