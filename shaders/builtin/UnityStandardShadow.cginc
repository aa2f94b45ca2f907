// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityStandardShadow.cginc. The shadow-caster pass of the Standard shader family
// (vertShadowCaster / fragShadowCaster): depth (or cube distance) via the UnityCG caster macros,
// with alpha test (_ALPHATEST_ON) and, for alpha-blended materials (_ALPHABLEND_ON,
// _ALPHAPREMULTIPLY_ON), dithered coverage from the 3D texture _DitherMaskLOD (SHADER_ABI.md §6).
// Written for varc from the documented behaviour; not derived from Unity's file.
#ifndef UNITY_STANDARD_SHADOW_INCLUDED
#define UNITY_STANDARD_SHADOW_INCLUDED

#include "UnityCG.cginc"
#include "UnityShaderVariables.cginc"
#include "UnityStandardConfig.cginc"
#include "UnityStandardUtils.cginc"

#if defined(_ALPHABLEND_ON) || defined(_ALPHAPREMULTIPLY_ON)
    #define UNITY_STANDARD_USE_SHADOW_UVS 1
    #if defined(UNITY_USE_DITHER_MASK_FOR_ALPHABLENDED_SHADOWS)
        #define UNITY_STANDARD_USE_DITHER_MASK 1
    #endif
#endif
#if defined(_ALPHATEST_ON)
    #define UNITY_STANDARD_USE_SHADOW_UVS 1
#endif
// An output struct is needed when the caster interpolates anything besides the position.
#if !defined(V2F_SHADOW_CASTER_NOPOS_IS_EMPTY) || defined(UNITY_STANDARD_USE_SHADOW_UVS)
    #define UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT 1
#endif

// Material properties read by the caster (the same names as UnityStandardInput.cginc).
half4 _Color;
half _Cutoff;
sampler2D _MainTex;
float4 _MainTex_ST;
#ifdef UNITY_STANDARD_USE_DITHER_MASK
sampler3D _DitherMaskLOD;   // 4 x 4 x 16: layer k covers k/15 of the 16 pixels of each 4x4 tile
#endif
#if defined(_ALPHAPREMULTIPLY_ON)
half _Metallic;
sampler2D _MetallicGlossMap;
#endif

struct VertexInput {
    float4 vertex : POSITION;
    float3 normal : NORMAL;
    float2 uv0 : TEXCOORD0;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

#ifdef UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT
struct VertexOutputShadowCaster {
    V2F_SHADOW_CASTER_NOPOS
    #if defined(UNITY_STANDARD_USE_SHADOW_UVS)
    float2 tex : TEXCOORD1;
    #endif
};
#endif

// Premultiplied materials cast the shadow of their reflective part too: alpha is raised to
// 1 - oneMinusReflectivity + alpha * oneMinusReflectivity (metallic workflow).
half ShadowCasterAlpha(float2 uv) {
    half alpha = tex2D(_MainTex, uv).a * _Color.a;
#if defined(_ALPHAPREMULTIPLY_ON)
    #if defined(_METALLICGLOSSMAP)
    half metallic = tex2D(_MetallicGlossMap, uv).r;
    #else
    half metallic = _Metallic;
    #endif
    half oneMinusReflectivity = OneMinusReflectivityFromMetallic(metallic);
    alpha = 1 - oneMinusReflectivity + alpha * oneMinusReflectivity;
#endif
    return alpha;
}

// The stereo eye index of the caster (empty: one eye per pass).
struct VertexOutputStereoShadowCaster {
    UNITY_VERTEX_OUTPUT_STEREO
};
// Token pasting through one level of expansion (e.g. a workflow's setup name and a suffix).
#define SHADOW_JOIN2(a, b) a##b
#define SHADOW_JOIN(a, b) SHADOW_JOIN2(a, b)

void vertShadowCaster(VertexInput v,
#ifdef UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT
    out VertexOutputShadowCaster o,
#endif
    out float4 opos : SV_POSITION)
{
    UNITY_SETUP_INSTANCE_ID(v);
#ifdef UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT
    UNITY_INITIALIZE_OUTPUT(VertexOutputShadowCaster, o);
#endif
    TRANSFER_SHADOW_CASTER_NOPOS(o, opos)
#if defined(UNITY_STANDARD_USE_SHADOW_UVS)
    o.tex = TRANSFORM_TEX(v.uv0, _MainTex);
#endif
}

half4 fragShadowCaster(
#ifdef UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT
    VertexOutputShadowCaster i
#endif
#ifdef UNITY_STANDARD_USE_DITHER_MASK
    #ifdef UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT
    ,
    #endif
    UNITY_VPOS_TYPE vpos : VPOS
#endif
    ) : SV_Target
{
#if defined(UNITY_STANDARD_USE_SHADOW_UVS)
    half alpha = ShadowCasterAlpha(i.tex);
    #if defined(UNITY_STANDARD_USE_DITHER_MASK)
        // Dither: the 4x4 screen tile picks the texel, alpha picks the coverage layer.
        half alphaRef = tex3D(_DitherMaskLOD, float3(vpos.xy * 0.25, alpha * 0.9375)).a;
        clip(alphaRef - 0.01);
    #else
        clip(alpha - _Cutoff);
    #endif
#endif
    SHADOW_CASTER_FRAGMENT(i)
}

#endif // UNITY_STANDARD_SHADOW_INCLUDED
