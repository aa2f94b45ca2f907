// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityStandardShadow.cginc. The shadow-caster pass of the Standard shader family
// (vertShadowCaster / fragShadowCaster, Unity 2022.3's signatures): depth (or cube distance) via
// the UnityCG caster macros, with alpha test (_ALPHATEST_ON), parallax-shifted uvs (_PARALLAXMAP)
// and, for alpha-blended materials (_ALPHABLEND_ON, _ALPHAPREMULTIPLY_ON), dithered coverage from
// the 3D texture _DitherMaskLOD (SHADER_ABI.md §6). Premultiplied materials cast the shadow of
// their reflective part too (SHADOW_ONEMINUSREFLECTIVITY of the workflow).
// Older signatures (void vertShadowCaster(..., out float4 opos) of Unity 5.6-2020.3) are not
// provided: both are entry points, and one program can have only one function of that name.
// Written for varc from the documented behaviour; not derived from Unity's file.
#ifndef UNITY_STANDARD_SHADOW_INCLUDED
#define UNITY_STANDARD_SHADOW_INCLUDED

#include "UnityCG.cginc"
#include "UnityShaderVariables.cginc"
#include "UnityStandardConfig.cginc"
#include "UnityStandardUtils.cginc"
#include "UnityLightingCommon.cginc" // _SpecColor

#if (defined(_ALPHABLEND_ON) || defined(_ALPHAPREMULTIPLY_ON)) && defined(UNITY_USE_DITHER_MASK_FOR_ALPHABLENDED_SHADOWS)
    #define UNITY_STANDARD_USE_DITHER_MASK 1
#endif
#if defined(_ALPHATEST_ON) || defined(_ALPHABLEND_ON) || defined(_ALPHAPREMULTIPLY_ON)
    #define UNITY_STANDARD_USE_SHADOW_UVS 1
#endif
// An output struct is needed when the caster interpolates anything besides the position.
#if !defined(V2F_SHADOW_CASTER_NOPOS_IS_EMPTY) || defined(UNITY_STANDARD_USE_SHADOW_UVS)
    #define UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT 1
#endif
#if defined(UNITY_STEREO_INSTANCING_ENABLED)
    #define UNITY_STANDARD_USE_STEREO_SHADOW_OUTPUT_STRUCT 1
#endif
// LOD cross-fading dithers the caster like the lit passes.
#if defined(LOD_FADE_CROSSFADE)
    #define _LOD_FADE_ON_ALPHA 1
#endif

// Material properties read by the caster (the same names as UnityStandardInput.cginc).
half4 _Color;
half _Cutoff;
sampler2D _MainTex;
float4 _MainTex_ST;
#ifdef UNITY_STANDARD_USE_DITHER_MASK
sampler3D _DitherMaskLOD;   // 4 x 4 x 16: layer k covers k/15 of the 16 pixels of each 4x4 tile
#endif
half _Metallic;
#ifdef _METALLICGLOSSMAP
sampler2D _MetallicGlossMap;
#endif
#ifdef _SPECGLOSSMAP
sampler2D _SpecGlossMap;
#endif
#if defined(UNITY_STANDARD_USE_SHADOW_UVS) && defined(_PARALLAXMAP)
sampler2D _ParallaxMap;
half _Parallax;
#endif

// 1 - reflectivity of each workflow at uv (UNITY_SETUP_BRDF_INPUT names the workflow).
half MetallicSetup_ShadowGetOneMinusReflectivity(half2 uv) {
#ifdef _METALLICGLOSSMAP
    half metallicity = tex2D(_MetallicGlossMap, uv).r;
#else
    half metallicity = _Metallic;
#endif
    return OneMinusReflectivityFromMetallic(metallicity);
}
half RoughnessSetup_ShadowGetOneMinusReflectivity(half2 uv) { return MetallicSetup_ShadowGetOneMinusReflectivity(uv); }
half SpecularSetup_ShadowGetOneMinusReflectivity(half2 uv) {
#ifdef _SPECGLOSSMAP
    half3 specColor = tex2D(_SpecGlossMap, uv).rgb;
#else
    half3 specColor = _SpecColor.rgb;
#endif
    return 1 - SpecularStrength(specColor);
}
// Token pasting through one level of expansion (e.g. a workflow's setup name and a suffix).
#define SHADOW_JOIN2(a, b) a##b
#define SHADOW_JOIN(a, b) SHADOW_JOIN2(a, b)
// The workflow the shader names (Unity's Standard shaders #define UNITY_SETUP_BRDF_INPUT);
// without one, the metallic workflow (what varc's caster and its CPU reference,
// runtime/reference MaterialResolver.cpp, have always assumed), without defining the name.
#ifdef UNITY_SETUP_BRDF_INPUT
#define SHADOW_ONEMINUSREFLECTIVITY SHADOW_JOIN(UNITY_SETUP_BRDF_INPUT, _ShadowGetOneMinusReflectivity)
#else
#define SHADOW_ONEMINUSREFLECTIVITY MetallicSetup_ShadowGetOneMinusReflectivity
#endif

struct VertexInput {
    float4 vertex : POSITION;
    float3 normal : NORMAL;
    float2 uv0 : TEXCOORD0;
#if defined(UNITY_STANDARD_USE_SHADOW_UVS) && defined(_PARALLAXMAP)
    half4 tangent : TANGENT;
#endif
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

// The clip position (and instance id, for cross-fading) every caster outputs.
struct VertexOutput {
    UNITY_POSITION(pos);
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

#ifdef UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT
struct VertexOutputShadowCaster {
    V2F_SHADOW_CASTER_NOPOS
    #if defined(UNITY_STANDARD_USE_SHADOW_UVS)
    float2 tex : TEXCOORD1;
        #if defined(_PARALLAXMAP)
    half3 viewDirForParallax : TEXCOORD2;   // tangent space, not normalised
        #endif
    #endif
};
#endif

#ifdef UNITY_STANDARD_USE_STEREO_SHADOW_OUTPUT_STRUCT
struct VertexOutputStereoShadowCaster {
    UNITY_VERTEX_OUTPUT_STEREO
};
#endif

VertexOutput vertShadowCaster(VertexInput v
#ifdef UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT
    , out VertexOutputShadowCaster o
#endif
#ifdef UNITY_STANDARD_USE_STEREO_SHADOW_OUTPUT_STRUCT
    , out VertexOutputStereoShadowCaster os
#endif
    )
{
    VertexOutput output;
    UNITY_SETUP_INSTANCE_ID(v);
    UNITY_INITIALIZE_OUTPUT(VertexOutput, output);
    UNITY_TRANSFER_INSTANCE_ID(v, output);
#ifdef UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT
    UNITY_INITIALIZE_OUTPUT(VertexOutputShadowCaster, o);
#endif
#ifdef UNITY_STANDARD_USE_STEREO_SHADOW_OUTPUT_STRUCT
    UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(os);
#endif
    TRANSFER_SHADOW_CASTER_NOPOS(o, output.pos)
#if defined(UNITY_STANDARD_USE_SHADOW_UVS)
    o.tex = TRANSFORM_TEX(v.uv0, _MainTex);
    #ifdef _PARALLAXMAP
    TANGENT_SPACE_ROTATION;
    o.viewDirForParallax = mul(rotation, ObjSpaceViewDir(v.vertex));
    #endif
#endif
    return output;
}

half4 fragShadowCaster(VertexOutput input
#ifdef UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT
    , VertexOutputShadowCaster i
#endif
    ) : SV_Target
{
    UNITY_SETUP_INSTANCE_ID(input);
#if defined(UNITY_STANDARD_USE_SHADOW_UVS)
    float2 uv = i.tex;
    #if defined(_PARALLAXMAP)
    half h = tex2D(_ParallaxMap, uv).g;
    uv += ParallaxOffset1Step(h, _Parallax, normalize(i.viewDirForParallax));
    #endif
    half alpha = tex2D(_MainTex, uv).a * _Color.a;
    #if defined(_ALPHATEST_ON)
    clip(alpha - _Cutoff);
    #endif
    #if defined(_ALPHABLEND_ON) || defined(_ALPHAPREMULTIPLY_ON)
        #if defined(_ALPHAPREMULTIPLY_ON)
    half oneMinusReflectivity = SHADOW_ONEMINUSREFLECTIVITY(uv);
    alpha = 1 - oneMinusReflectivity + alpha * oneMinusReflectivity;
        #endif
        #if defined(UNITY_STANDARD_USE_DITHER_MASK)
    // Dither: the 4x4 screen tile picks the texel, alpha picks the coverage layer.
    half alphaRef = tex3D(_DitherMaskLOD, float3(input.pos.xy * 0.25, alpha * 0.9375)).a;
    clip(alphaRef - 0.01);
        #else
    clip(alpha - _Cutoff);
        #endif
    #endif
#endif
#ifdef _LOD_FADE_ON_ALPHA
    UNITY_APPLY_DITHER_CROSSFADE(input.pos.xy);
#endif
    SHADOW_CASTER_FRAGMENT(i)
}

#endif // UNITY_STANDARD_SHADOW_INCLUDED
