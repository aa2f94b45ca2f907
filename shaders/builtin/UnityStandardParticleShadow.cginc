// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityStandardParticleShadow.cginc. The shadow-caster pass of the Standard
// particle shaders: depth via the UnityCG caster macros, with the particle's albedo alpha (times
// its colour, blended between flip-book frames with _REQUIRE_UV2) cut at _Cutoff
// (_ALPHATEST_ON) or dithered through _DitherMaskLOD (alpha-blended materials), as
// UnityStandardShadow.cginc does for meshes. Written for varc; not derived from Unity.
#ifndef UNITY_STANDARD_PARTICLE_SHADOW_INCLUDED
#define UNITY_STANDARD_PARTICLE_SHADOW_INCLUDED

#if _REQUIRE_UV2
#define _FLIPBOOK_BLENDING 1
#endif

#include "UnityCG.cginc"
#include "UnityShaderVariables.cginc"
#include "UnityStandardConfig.cginc"
#include "UnityStandardUtils.cginc"
#include "UnityStandardParticleInstancing.cginc"

#if defined(_ALPHABLEND_ON) || defined(_ALPHAPREMULTIPLY_ON)
    #define UNITY_STANDARD_USE_SHADOW_UVS 1
    #if defined(UNITY_USE_DITHER_MASK_FOR_ALPHABLENDED_SHADOWS)
        #define UNITY_STANDARD_USE_DITHER_MASK 1
    #endif
#endif
#if defined(_ALPHATEST_ON)
    #define UNITY_STANDARD_USE_SHADOW_UVS 1
#endif
#if !defined(V2F_SHADOW_CASTER_NOPOS_IS_EMPTY) || defined(UNITY_STANDARD_USE_SHADOW_UVS)
    #define UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT 1
#endif
// Single-pass stereo instancing is not supported by varc (no stereo output struct).

half4 _Color;
sampler2D _MainTex;
float4 _MainTex_ST;
half _Metallic;
#if defined(_ALPHATEST_ON)
half _Cutoff;
#endif
#if defined(_METALLICGLOSSMAP)
sampler2D _MetallicGlossMap;
#endif
#if defined(UNITY_STANDARD_USE_DITHER_MASK)
sampler3D _DitherMaskLOD;   // 4 x 4 x 16: layer k covers k/15 of the 16 pixels of each 4x4 tile
#endif

struct VertexInput {
    float4 vertex : POSITION;
    float3 normal : NORMAL;
    fixed4 color : COLOR;
#if defined(_FLIPBOOK_BLENDING) && !defined(UNITY_PARTICLE_INSTANCING_ENABLED)
    float4 texcoords : TEXCOORD0;
    float texcoordBlend : TEXCOORD1;
#else
    float2 texcoords : TEXCOORD0;
#endif
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

#ifdef UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT
struct VertexOutputShadowCaster {
    V2F_SHADOW_CASTER_NOPOS
#if defined(UNITY_STANDARD_USE_SHADOW_UVS)
    float2 texcoord : TEXCOORD1;
#if defined(_FLIPBOOK_BLENDING)
    float3 texcoord2AndBlend : TEXCOORD2;
#endif
    fixed4 color : TEXCOORD3;
#endif
};
#endif

// 1 - reflectivity of a metallic particle (metallic from _MetallicGlossMap.r or _Metallic).
half MetallicSetup_ShadowGetOneMinusReflectivity(half2 uv) {
#if defined(_METALLICGLOSSMAP)
    half metallicity = tex2D(_MetallicGlossMap, uv).r;
#else
    half metallicity = _Metallic;
#endif
    return OneMinusReflectivityFromMetallic(metallicity);
}

// The stereo eye of the caster, with single-pass instanced stereo only.
#if defined(UNITY_STEREO_INSTANCING_ENABLED)
#define UNITY_STANDARD_USE_STEREO_SHADOW_OUTPUT_STRUCT 1
#endif
#ifdef UNITY_STANDARD_USE_STEREO_SHADOW_OUTPUT_STRUCT
struct VertexOutputStereoShadowCaster {
    UNITY_VERTEX_OUTPUT_STEREO
};
#endif

void vertParticleShadowCaster(VertexInput v,
#ifdef UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT
    out VertexOutputShadowCaster o,
#endif
#ifdef UNITY_STANDARD_USE_STEREO_SHADOW_OUTPUT_STRUCT
    out VertexOutputStereoShadowCaster os,
#endif
    out float4 opos : SV_POSITION)
{
    UNITY_SETUP_INSTANCE_ID(v);
#ifdef UNITY_STANDARD_USE_SHADOW_OUTPUT_STRUCT
    UNITY_INITIALIZE_OUTPUT(VertexOutputShadowCaster, o);
#endif
#ifdef UNITY_STANDARD_USE_STEREO_SHADOW_OUTPUT_STRUCT
    UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(os);
#endif
    TRANSFER_SHADOW_CASTER_NOPOS(o, opos)
#if defined(UNITY_STANDARD_USE_SHADOW_UVS)
#if defined(_FLIPBOOK_BLENDING) && !defined(UNITY_PARTICLE_INSTANCING_ENABLED)
    o.texcoord = TRANSFORM_TEX(v.texcoords.xy, _MainTex);
    o.texcoord2AndBlend.xy = TRANSFORM_TEX(v.texcoords.zw, _MainTex);
    o.texcoord2AndBlend.z = v.texcoordBlend;
#elif defined(_FLIPBOOK_BLENDING)
    vertInstancingUVs(v.texcoords.xy, o.texcoord, o.texcoord2AndBlend);
    o.texcoord = TRANSFORM_TEX(o.texcoord, _MainTex);
    o.texcoord2AndBlend.xy = TRANSFORM_TEX(o.texcoord2AndBlend.xy, _MainTex);
#else
    vertInstancingUVs(v.texcoords.xy, o.texcoord);
    o.texcoord = TRANSFORM_TEX(o.texcoord, _MainTex);
#endif
    o.color = v.color;
#endif
}

half4 fragParticleShadowCaster(
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
    half alpha = tex2D(_MainTex, i.texcoord).a;
    #if defined(_FLIPBOOK_BLENDING)
    alpha = lerp(alpha, tex2D(_MainTex, i.texcoord2AndBlend.xy).a, i.texcoord2AndBlend.z);
    #endif
    alpha *= _Color.a * i.color.a;
    #if defined(UNITY_STANDARD_USE_DITHER_MASK)
        #if defined(_ALPHAPREMULTIPLY_ON)
        half oneMinusReflectivity = MetallicSetup_ShadowGetOneMinusReflectivity(i.texcoord);
        alpha = 1 - oneMinusReflectivity + alpha * oneMinusReflectivity;
        #endif
        half alphaRef = tex3D(_DitherMaskLOD, float3(vpos.xy * 0.25, alpha * 0.9375)).a;
        clip(alphaRef - 0.01);
    #else
        clip(alpha - _Cutoff);
    #endif
#endif
    SHADOW_CASTER_FRAGMENT(i)
}

#endif // UNITY_STANDARD_PARTICLE_SHADOW_INCLUDED
