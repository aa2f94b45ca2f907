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

// ---------------------------------------------------------------------------------------------
// More of Unity's instancing API (issue #27, docs/BUILTIN_API.md).
// ---------------------------------------------------------------------------------------------
// Unity 5.6's spelling of the per-instance block, and the plain block of 2017.4+.
#define UNITY_INSTANCING_CBUFFER_START(name) UNITY_INSTANCING_BUFFER_START(name)
#define UNITY_INSTANCING_CBUFFER_END CBUFFER_END
#define UNITY_INSTANCING_CBUFFER_SCOPE_BEGIN(name) CBUFFER_START(name)
#define UNITY_INSTANCING_CBUFFER_SCOPE_END CBUFFER_END
// Unity 2020.3 merges its built-in per-instance blocks; here each property is its own array.
#define UNITY_ACCESS_MERGED_INSTANCED_PROP(arr, var) UNITY_ACCESS_INSTANCED_PROP(arr, var)

// The DEFAULT_ spellings Unity keeps so that a shader may redefine the plain ones.
#define DEFAULT_UNITY_SETUP_INSTANCE_ID(input) UNITY_SETUP_INSTANCE_ID(input)
#define DEFAULT_UNITY_VERTEX_OUTPUT_STEREO UNITY_VERTEX_OUTPUT_STEREO
#define DEFAULT_UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(output) UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(output)
#define DEFAULT_UNITY_TRANSFER_VERTEX_OUTPUT_STEREO(input, output) UNITY_TRANSFER_VERTEX_OUTPUT_STEREO(input, output)
#define DEFAULT_UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX(input) UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX(input)
// One eye per pass (no single-pass stereo): the eye-index plumbing is empty, as the stereo
// macros of VarcInstancing.hlsl.
#define UNITY_VERTEX_OUTPUT_STEREO_EYE_INDEX
#define UNITY_INITIALIZE_OUTPUT_STEREO_EYE_INDEX(output)
#define DEFAULT_UNITY_VERTEX_OUTPUT_STEREO_EYE_INDEX UNITY_VERTEX_OUTPUT_STEREO_EYE_INDEX
#define DEFAULT_UNITY_INITIALIZE_OUTPUT_STEREO_EYE_INDEX(output) UNITY_INITIALIZE_OUTPUT_STEREO_EYE_INDEX(output)

#if defined(UNITY_INSTANCING_ENABLED)
    // The runtime draws every instanced batch with firstInstance = 0, so SV_InstanceID is
    // already the index into the per-instance arrays.
    static const int unity_BaseInstanceID = 0;
    void UnitySetupInstanceID(uint inputInstanceID) { unity_InstanceID = inputInstanceID + unity_BaseInstanceID; }
    // The compound matrices: UNITY_MATRIX_MVP & co. (UnityShaderVariables.cginc) are computed
    // where they are used, from the instance's unity_ObjectToWorld defined above, so there is
    // nothing to precompute; the _Instanced names are those same expressions.
    void UnitySetupCompoundMatrices() {}
    #define unity_MatrixMVP_Instanced UNITY_MATRIX_MVP
    #define unity_MatrixMV_Instanced UNITY_MATRIX_MV
    #define unity_MatrixTMV_Instanced UNITY_MATRIX_T_MV
    #define unity_MatrixITMV_Instanced UNITY_MATRIX_IT_MV
#endif

#endif // UNITY_INSTANCING_INCLUDED
