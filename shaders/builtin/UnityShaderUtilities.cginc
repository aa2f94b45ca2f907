// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityShaderUtilities.cginc. The object-to-clip transform every CG program can
// use without including UnityCG.cginc (Unity includes this file from UnityShaderVariables.cginc,
// which CGPROGRAM blocks see implicitly). Written for varc.
#ifndef UNITY_SHADER_UTILITIES_INCLUDED
#define UNITY_SHADER_UTILITIES_INCLUDED

#include "UnityShaderVariables.cginc"

// mul(M, v) with column vectors; matrices as documented in SHADER_ABI.md.
inline float4 UnityObjectToClipPos(in float3 pos) {
    return mul(UNITY_MATRIX_VP, mul(unity_ObjectToWorld, float4(pos, 1.0)));
}
inline float4 UnityObjectToClipPos(float4 pos) { return UnityObjectToClipPos(pos.xyz); }

// Omni-directional stereo (ODS) capture renders 360-degree stereo cube maps by moving each
// vertex sideways by the eye's offset: |ipd| (signed half the eye separation) along the
// horizontal tangent of the circle the eyes sweep, cross(view direction, up), normalised.
inline float3 ODSOffset(float3 worldPos, float ipd) {
    float3 dir = worldPos - _WorldSpaceCameraPos.xyz;
    float3 tangent = cross(dir, float3(0.0, 1.0, 0.0));
    float len2 = max(dot(tangent, tangent), 1e-8);
    return tangent * (ipd * rsqrt(len2));
}
// varc renders no ODS captures (no STEREO_CUBEMAP_RENDER_ON target): the plain transform.
inline float4 UnityObjectToClipPosODS(float3 inPos) { return UnityObjectToClipPos(inPos); }

#endif // UNITY_SHADER_UTILITIES_INCLUDED
