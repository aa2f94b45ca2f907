// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityDeferredLibrary.cginc. Helpers for deferred light-pass shaders: the light
// pass inputs (G-buffer depth, _LightPos/_LightDir/_LightColor, falloff and cookie textures), the
// light-volume vertex program, world position from depth, and per-light attenuation and shadows
// as in docs/LIGHTING.md §10. Conventions: docs/SHADER_ABI.md §4.8, §5; formulas:
// docs/LIGHTING.md §3, §6. Written for varc.
#ifndef UNITY_DEFERRED_LIBRARY_INCLUDED
#define UNITY_DEFERRED_LIBRARY_INCLUDED

#include "UnityCG.cginc"
#include "UnityShadowLibrary.cginc"

UNITY_DECLARE_DEPTH_TEXTURE(_CameraDepthTexture);

// Per light (one light-pass draw per light).
CBUFFER_START(UnityDeferredLight)
    float4 _LightDir;          // direction the light travels (world, unit), directional and spot
    float4 _LightPos;          // (world position, 1/range^2)
    float4 _LightColor;        // colour * intensity (linear)
    float4 unity_LightmapFade; // reserved (0)
    float _LightAsQuad;        // 1: full-screen quad whose NORMALs are camera rays; 0: light volume
CBUFFER_END

#if defined(POINT_COOKIE)
samplerCUBE_float _LightTexture0;  // cube cookie (alpha)
#else
sampler2D_float _LightTexture0;    // spot / directional cookie (alpha)
#endif
sampler2D_float _LightTextureB0;   // falloff lookup indexed by d^2/range^2 (.r)
#if defined(SHADOWS_SCREEN)
sampler2D _ShadowMapTexture;       // screen-space shadow mask of the directional light (.r)
#endif

struct unity_v2f_deferred {
    float4 pos : SV_POSITION;
    float4 uv : TEXCOORD0;
    float3 ray : TEXCOORD1;
};

// Light volumes: the ray is the camera-space (+z forward) position; quads carry it in NORMAL.
unity_v2f_deferred vert_deferred(float4 vertex : POSITION, float3 normal : NORMAL) {
    unity_v2f_deferred o;
    o.pos = UnityObjectToClipPos(vertex);
    o.uv = ComputeScreenPos(o.pos);
    o.ray = UnityObjectToViewPos(vertex) * float3(-1, -1, 1);
    o.ray = lerp(o.ray, normal, _LightAsQuad);
    return o;
}

float UnityDeferredComputeFadeDistance(float3 wpos, float z) {
    return UnityComputeShadowFadeDistance(wpos, z);
}

// Realtime shadow of the current light (1 = lit), per shadow keyword.
half UnityDeferredSampleRealtimeShadow(half fade, float3 vec, float2 uv) {
    half shadowAttenuation = 1.0;
#if defined(DIRECTIONAL) || defined(DIRECTIONAL_COOKIE)
    #if defined(SHADOWS_SCREEN)
    shadowAttenuation = tex2D(_ShadowMapTexture, uv).r;
    #endif
#elif defined(SPOT)
    #if defined(SHADOWS_DEPTH)
    shadowAttenuation = UnitySampleShadowmap(mul(unity_WorldToShadow[0], float4(vec, 1)));
    #endif
#else
    #if defined(SHADOWS_CUBE)
    shadowAttenuation = UnitySampleShadowmap(vec);
    #endif
#endif
    return shadowAttenuation;
}

// Shadow with the distance fade: saturate(realtime + fade), or exactly 1 without a shadow keyword.
// vec: world position for spot and directional lights, worldPos - _LightPos.xyz for point lights.
half UnityDeferredComputeShadow(float3 vec, float fadeDist, float2 uv) {
#if defined(SHADOWS_SCREEN) || defined(SHADOWS_DEPTH) || defined(SHADOWS_CUBE)
    half fade = UnityComputeShadowFade(fadeDist);
    return saturate(UnityDeferredSampleRealtimeShadow(fade, vec, uv) + fade);
#else
    return 1.0;
#endif
}

// World position, screen uv, light direction, attenuation and fade distance of a light-pass pixel
// (docs/LIGHTING.md §10):
//   SPOT         atten = cookie(uvCookie.xy / uvCookie.w, bias -8).w * (uvCookie.w < 0)
//                        * falloff(d^2 * _LightPos.w).r * shadow
//   DIRECTIONAL  atten = shadow (* cookie(lc.xy, bias -8).w for DIRECTIONAL_COOKIE), L = -_LightDir
//   POINT        atten = falloff(d^2 * _LightPos.w).r * shadow (* cubeCookie(lc, bias -8).w for POINT_COOKIE)
//   no keyword   atten = 0
void UnityDeferredCalculateLightParams(unity_v2f_deferred i, out float3 outWorldPos, out float2 outUV,
                                       out half3 outLightDir, out float outAtten, out float outFadeDist)
{
    i.ray = i.ray * (_ProjectionParams.z / i.ray.z);
    float2 uv = i.uv.xy / i.uv.w;
    float depth = Linear01Depth(SAMPLE_DEPTH_TEXTURE(_CameraDepthTexture, uv));
    float4 vpos = float4(i.ray * depth, 1);
    float3 wpos = mul(unity_CameraToWorld, vpos).xyz;
    float fadeDist = UnityDeferredComputeFadeDistance(wpos, vpos.z);

    float atten = 0;
    half3 lightDir = 0;
#if defined(SPOT)
    float3 tolight = _LightPos.xyz - wpos;
    lightDir = normalize(tolight);
    float4 uvCookie = mul(unity_WorldToLight, float4(wpos, 1));
    atten = tex2Dbias(_LightTexture0, float4(uvCookie.xy / uvCookie.w, 0, -8)).w;
    atten *= uvCookie.w < 0;
    float att = dot(tolight, tolight) * _LightPos.w;
    atten *= tex2D(_LightTextureB0, att.rr).UNITY_ATTEN_CHANNEL;
    atten *= UnityDeferredComputeShadow(wpos, fadeDist, uv);
#elif defined(DIRECTIONAL) || defined(DIRECTIONAL_COOKIE)
    lightDir = -_LightDir.xyz;
    atten = UnityDeferredComputeShadow(wpos, fadeDist, uv);
    #if defined(DIRECTIONAL_COOKIE)
    atten *= tex2Dbias(_LightTexture0, float4(mul(unity_WorldToLight, float4(wpos, 1)).xy, 0, -8)).w;
    #endif
#elif defined(POINT) || defined(POINT_COOKIE)
    float3 tolight = wpos - _LightPos.xyz;
    lightDir = -normalize(tolight);
    float att = dot(tolight, tolight) * _LightPos.w;
    atten = tex2D(_LightTextureB0, att.rr).UNITY_ATTEN_CHANNEL;
    atten *= UnityDeferredComputeShadow(tolight, fadeDist, uv);
    #if defined(POINT_COOKIE)
    atten *= texCUBEbias(_LightTexture0, float4(mul(unity_WorldToLight, float4(wpos, 1)).xyz, -8)).w;
    #endif
#endif

    outWorldPos = wpos;
    outUV = uv;
    outLightDir = lightDir;
    outAtten = atten;
    outFadeDist = fadeDist;
}

// The G-buffer's fifth target: the baked shadowmask of each texel (SHADOWS_SHADOWMASK).
sampler2D _CameraGBufferTexture4;
// Baked occlusion of the current light at uv: the shadowmask channel unity_OcclusionMaskSelector
// picks, or 1 without SHADOWS_SHADOWMASK.
half UnityDeferredSampleShadowMask(float2 uv) {
    half shadowMaskAttenuation = 1.0;
#if defined(SHADOWS_SHADOWMASK)
    half4 shadowMask = tex2D(_CameraGBufferTexture4, uv);
    shadowMaskAttenuation = saturate(dot(shadowMask, unity_OcclusionMaskSelector));
#endif
    return shadowMaskAttenuation;
}

#endif // UNITY_DEFERRED_LIBRARY_INCLUDED
