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

#endif // UNITY_LIGHTING_COMMON_INCLUDED
