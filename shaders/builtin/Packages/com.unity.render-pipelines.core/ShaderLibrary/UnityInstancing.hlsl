// SPDX-License-Identifier: Apache-2.0
// varc built-in: SRP core ShaderLibrary/UnityInstancing.hlsl. GPU instancing for scriptable-
// pipeline shaders: the shared macros (VarcInstancing.hlsl) plus, when INSTANCING_ON is set,
// UNITY_MATRIX_M / UNITY_MATRIX_I_M redirected to per-instance arrays. The shader defines
// UNITY_MATRIX_M (e.g. as unity_ObjectToWorld) before including this file. Written for varc.
#ifndef UNITY_INSTANCING_INCLUDED
#define UNITY_INSTANCING_INCLUDED

#include "VarcInstancing.hlsl"

#if defined(UNITY_INSTANCING_ENABLED)
    UNITY_INSTANCING_BUFFER_START(unity_Builtins0)
        UNITY_DEFINE_INSTANCED_PROP(float4x4, unity_ObjectToWorld)
        UNITY_DEFINE_INSTANCED_PROP(float4x4, unity_WorldToObject)
    UNITY_INSTANCING_BUFFER_END(unity_Builtins0)
    #undef UNITY_MATRIX_M
    #undef UNITY_MATRIX_I_M
    #define UNITY_MATRIX_M UNITY_ACCESS_INSTANCED_PROP(unity_Builtins0, unity_ObjectToWorld)
    #define UNITY_MATRIX_I_M UNITY_ACCESS_INSTANCED_PROP(unity_Builtins0, unity_WorldToObject)
#endif

#endif // UNITY_INSTANCING_INCLUDED
