// SPDX-License-Identifier: Apache-2.0
// varc lighting library: the program of SinglePassLit.shader, on the SRP core subset
// (Common.hlsl, UnityInstancing.hlsl). The shader declares its own built-in blocks, as SRP
// shaders do; the runtime fills them by name (docs/SHADER_ABI.md §4.12).
//
// Light j of the light buffer (world space, colours linear, colour * intensity):
//   _VisibleLightColors[j]                 (rgb, -)
//   _VisibleLightDirectionsOrPositions[j]  directional: (unit direction towards the light, 0);
//                                          point/spot: (position, 1)
//   _VisibleLightAttenuations[j]           (1/range^2 or 0 for directional, -, a, b) with the spot
//                                          fade a = 1/max(cos(inner) - cos(outer), 0.001),
//                                          b = -cos(outer) * a; non-spot lights: a = 0, b = 1
//   _VisibleLightSpotDirections[j]         spot: (unit direction towards the light = -forward, 0)
// Irradiance of light j at p with unit normal n (LIGHTING.md §8.4):
//   L = pos.xyz - p * pos.w,  d2 = |L|^2,  l = L / |L|
//   rangeFade = (saturate(1 - (d2 * att.x)^2))^2
//   spotFade  = (saturate(dot(spotDir, l) * att.z + att.w))^2
//   E_j = colour * saturate(dot(n, l)) * rangeFade * spotFade / max(d2, 1e-5)
// Directional lights store a unit vector, so d2 = 1 and both fades are 1.
#ifndef VARC_SINGLE_PASS_LIT_INCLUDED
#define VARC_SINGLE_PASS_LIT_INCLUDED

#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/Common.hlsl"

#define VARC_MAX_VISIBLE_LIGHTS 16

CBUFFER_START(UnityPerFrame)
    float4x4 unity_MatrixVP;
CBUFFER_END

CBUFFER_START(UnityPerDraw)
    float4x4 unity_ObjectToWorld;
    float4x4 unity_WorldToObject;
    float4 unity_LightIndicesOffsetAndCount;   // y = number of lights touching the draw
    float4 unity_4LightIndices0;               // per-pixel lights: indices into the light buffer
    float4 unity_4LightIndices1;               // per-vertex lights
CBUFFER_END

CBUFFER_START(_LightBuffer)
    float4 _VisibleLightColors[VARC_MAX_VISIBLE_LIGHTS];
    float4 _VisibleLightDirectionsOrPositions[VARC_MAX_VISIBLE_LIGHTS];
    float4 _VisibleLightAttenuations[VARC_MAX_VISIBLE_LIGHTS];
    float4 _VisibleLightSpotDirections[VARC_MAX_VISIBLE_LIGHTS];
CBUFFER_END

#define UNITY_MATRIX_M unity_ObjectToWorld
#define UNITY_MATRIX_I_M unity_WorldToObject
#include "Packages/com.unity.render-pipelines.core/ShaderLibrary/UnityInstancing.hlsl"

UNITY_INSTANCING_BUFFER_START(PerInstance)
    UNITY_DEFINE_INSTANCED_PROP(float4, _Color)
UNITY_INSTANCING_BUFFER_END(PerInstance)

struct SinglePassAttributes {
    float4 positionOS : POSITION;
    float3 normalOS : NORMAL;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

struct SinglePassVaryings {
    float4 positionCS : SV_POSITION;
    float3 normalWS : TEXCOORD0;
    float3 positionWS : TEXCOORD1;
    float3 vertexLighting : TEXCOORD2;   // irradiance of the per-vertex lights
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

// Irradiance from the visible light at `index` (clamped into the buffer).
float3 VisibleLightIrradiance(int index, float3 normalWS, float3 positionWS) {
    int j = clamp(index, 0, VARC_MAX_VISIBLE_LIGHTS - 1);
    float4 positionOrDirection = _VisibleLightDirectionsOrPositions[j];
    float4 attenuation = _VisibleLightAttenuations[j];

    float3 toLight = positionOrDirection.xyz - positionWS * positionOrDirection.w;
    float distanceSq = dot(toLight, toLight);
    float3 lightDir = toLight * rsqrt(max(distanceSq, 1e-10));

    float rangeFade = saturate(1.0 - Sq(distanceSq * attenuation.x));
    float spotFade = saturate(dot(_VisibleLightSpotDirections[j].xyz, lightDir) * attenuation.z + attenuation.w);
    float lambert = saturate(dot(normalWS, lightDir));
    return _VisibleLightColors[j].rgb * (lambert * Sq(rangeFade) * Sq(spotFade) / max(distanceSq, 1e-5));
}

// Light count of this draw, capped at `limit`.
int DrawLightCount(int limit) {
    return min((int)unity_LightIndicesOffsetAndCount.y, limit);
}

SinglePassVaryings SinglePassVertex(SinglePassAttributes input) {
    SinglePassVaryings output;
    UNITY_SETUP_INSTANCE_ID(input);
    UNITY_TRANSFER_INSTANCE_ID(input, output);
    float4 positionWS = mul(UNITY_MATRIX_M, float4(input.positionOS.xyz, 1.0));
    output.positionCS = mul(unity_MatrixVP, positionWS);
    output.positionWS = positionWS.xyz;
    // Inverse-transpose transform, correct for non-uniform scale too.
    output.normalWS = SafeNormalize(mul(input.normalOS, (float3x3)UNITY_MATRIX_I_M));

    // Lights 4..7 of the draw, per vertex.
    output.vertexLighting = 0;
    for (int k = 4; k < DrawLightCount(8); k++) {
        output.vertexLighting += VisibleLightIrradiance((int)unity_4LightIndices1[k - 4],
                                                        output.normalWS, output.positionWS);
    }
    return output;
}

float4 SinglePassFragment(SinglePassVaryings input) : SV_TARGET {
    UNITY_SETUP_INSTANCE_ID(input);
    float3 normalWS = normalize(input.normalWS);
    float3 albedo = UNITY_ACCESS_INSTANCED_PROP(PerInstance, _Color).rgb;

    // Lights 0..3 of the draw, per pixel, on top of the interpolated vertex lights.
    float3 irradiance = input.vertexLighting;
    for (int k = 0; k < DrawLightCount(4); k++) {
        irradiance += VisibleLightIrradiance((int)unity_4LightIndices0[k], normalWS, input.positionWS);
    }
    return float4(albedo * irradiance, 1);
}

#endif // VARC_SINGLE_PASS_LIT_INCLUDED
