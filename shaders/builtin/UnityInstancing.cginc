// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityInstancing.cginc. GPU instancing for built-in-pipeline shaders: the shared
// macros (VarcInstancing.hlsl) plus per-instance object matrices replacing unity_ObjectToWorld
// and unity_WorldToObject when INSTANCING_ON is set. Written for varc.
#ifndef UNITY_INSTANCING_INCLUDED
#define UNITY_INSTANCING_INCLUDED

#include "HLSLSupport.cginc"
#include "UnityShaderVariables.cginc"
#include "VarcInstancing.hlsl"

#if defined(UNITY_INSTANCING_ENABLED)
    // Block UnityInstancing_unity_Builtins0 { float4x4 unity_ObjectToWorldArray[N];
    // float4x4 unity_WorldToObjectArray[N]; }, element i = instance i.
    UNITY_INSTANCING_BUFFER_START(unity_Builtins0)
        UNITY_DEFINE_INSTANCED_PROP(float4x4, unity_ObjectToWorld)
        UNITY_DEFINE_INSTANCED_PROP(float4x4, unity_WorldToObject)
    UNITY_INSTANCING_BUFFER_END(unity_Builtins0)
    #define unity_ObjectToWorld UNITY_ACCESS_INSTANCED_PROP(unity_Builtins0, unity_ObjectToWorld)
    #define unity_WorldToObject UNITY_ACCESS_INSTANCED_PROP(unity_Builtins0, unity_WorldToObject)
    // UnityObjectToClipPos (UnityShaderUtilities.cginc) was compiled against the plain matrix
    // before the lines above: the instanced programs use these, with the instance's matrix.
    inline float4 UnityObjectToClipPosInstanced(in float3 pos) {
        return mul(UNITY_MATRIX_VP, mul(unity_ObjectToWorld, float4(pos, 1.0)));
    }
    inline float4 UnityObjectToClipPosInstanced(float4 pos) { return UnityObjectToClipPosInstanced(pos.xyz); }
    #define UnityObjectToClipPos UnityObjectToClipPosInstanced
#endif

#endif // UNITY_INSTANCING_INCLUDED
