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

#endif // UNITY_SHADER_UTILITIES_INCLUDED
