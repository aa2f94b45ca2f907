// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityGBuffer.cginc. The deferred G-buffer layout as a struct, with the packing
// used by G-buffer passes and the unpacking used by light and post passes. Layout (the one of
// shaders/deferred/GBuffer.shader and docs/SHADER_ABI.md §6):
//   RT0 rgb = diffuse colour,  a = occlusion
//   RT1 rgb = specular colour, a = smoothness
//   RT2 rgb = world normal * 0.5 + 0.5, a = 1
// RT3 (emission + ambient) is written by the pass itself. Written for varc.
#ifndef UNITY_GBUFFER_INCLUDED
#define UNITY_GBUFFER_INCLUDED

#include "HLSLSupport.cginc"

struct UnityStandardData {
    half3 diffuseColor;
    half occlusion;
    half3 specularColor;
    half smoothness;
    float3 normalWorld;   // unit length
};

void UnityStandardDataToGbuffer(UnityStandardData data, out half4 outGBuffer0, out half4 outGBuffer1, out half4 outGBuffer2) {
    outGBuffer0 = half4(data.diffuseColor, data.occlusion);
    outGBuffer1 = half4(data.specularColor, data.smoothness);
    outGBuffer2 = half4(data.normalWorld * 0.5f + 0.5f, 1.0f);
}

UnityStandardData UnityStandardDataFromGbuffer(half4 inGBuffer0, half4 inGBuffer1, half4 inGBuffer2) {
    UnityStandardData data;
    data.diffuseColor = inGBuffer0.rgb;
    data.occlusion = inGBuffer0.a;
    data.specularColor = inGBuffer1.rgb;
    data.smoothness = inGBuffer1.a;
    data.normalWorld = normalize((float3)inGBuffer2.rgb * 2 - 1);
    return data;
}

// Weighted layers (e.g. decals) summed into the G-buffer with additive blending: every
// linearly encoded value is scaled by the weight (diffuse rgb, specular rgb and smoothness,
// normal rgb); occlusion (gbuffer0.a) is left as is.
void UnityStandardDataApplyWeightToGbuffer(inout half4 inOutGBuffer0, inout half4 inOutGBuffer1, inout half4 inOutGBuffer2, half alpha) {
    inOutGBuffer0.rgb *= alpha;
    inOutGBuffer1 *= alpha;
    inOutGBuffer2.rgb *= alpha;
}

#endif // UNITY_GBUFFER_INCLUDED
