// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityLightingCommon.cginc. The light description structs passed to the BRDFs
// (UnityLight, UnityIndirect, UnityGI) and the legacy specular colour property. Written for varc.
#ifndef UNITY_LIGHTING_COMMON_INCLUDED
#define UNITY_LIGHTING_COMMON_INCLUDED

#include "UnityShaderVariables.cginc"

// _LightColor0 lives in the UnityLighting block (UnityShaderVariables.cginc).
// _SpecColor is a material property of the legacy BlinnPhong model (block $Global).
fixed4 _SpecColor;

struct UnityLight {
    half3 color;   // radiance reaching the surface: light colour * attenuation * shadow
    half3 dir;     // unit vector from the surface towards the light, world space
    half ndotl;    // legacy (Unity 5.4): set by some shaders, never read by varc's BRDFs
};

struct UnityIndirect {
    half3 diffuse;   // irradiance-like diffuse term (SH, vertex lights, lightmaps)
    half3 specular;  // pre-filtered reflection radiance
};

struct UnityGI {
    UnityLight light;
    UnityIndirect indirect;
};

// Everything the global-illumination functions (UnityGlobalIllumination.cginc) need to know
// about the surface point: the main light, position, view direction, attenuation, the ambient
// already gathered per vertex, the two reflection probes and the lightmap uvs.
struct UnityGIInput {
    UnityLight light;      // the pixel light; color is multiplied by atten in UnityGI_Base
    float3 worldPos;
    half3 worldViewDir;    // unit vector from the surface towards the camera
    half atten;            // light attenuation * shadow
    half3 ambient;         // per-vertex SH / vertex lights (ShadeSHPerVertex)
    float4 lightmapUV;     // xy = baked lightmap uv, zw = realtime lightmap uv
    float4 boxMin[2];      // probe boxes; boxMin[0].w = blend weight of probe 0
    float4 boxMax[2];
    float4 probePosition[2]; // w > 0: box projection
    float4 probeHDR[2];    // DecodeHDR instructions of each probe
};

#endif // UNITY_LIGHTING_COMMON_INCLUDED
