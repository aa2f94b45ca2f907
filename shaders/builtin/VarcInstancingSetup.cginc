// SPDX-License-Identifier: Apache-2.0
// varc built-in: the per-vertex set-up of UnityInstancing.cginc (included at its end): instance
// ID and stereo eye from SV_InstanceID, the procedural function of
// `#pragma instancing_options procedural:FUNC`, and the DEFAULT_ and legacy macro spellings.
// Written for varc.
#ifndef VARC_INSTANCING_SETUP_INCLUDED
#define VARC_INSTANCING_SETUP_INCLUDED

#if defined(VARC_ANY_INSTANCING)
    // The runtime draws every instanced batch with firstInstance = 0, so SV_InstanceID is
    // already the index into the per-instance arrays.
    static const int unity_BaseInstanceID = 0;
    // Instances in the draw; varc's runtime does not fill this block (it reads 0).
    CBUFFER_START(UnityDrawCallInfo)
        int unity_InstanceCount;
    CBUFFER_END
    // With stereo instancing each object is drawn twice per instance: even SV_InstanceIDs are
    // the left eye, odd ones the right, and the object's instance is the pair's index.
    void UnitySetupInstanceID(uint inputInstanceID) {
    #if defined(UNITY_STEREO_INSTANCING_ENABLED)
        unity_StereoEyeIndex = inputInstanceID & 0x01;
        unity_InstanceID = unity_BaseInstanceID + (inputInstanceID >> 1);
    #else
        unity_InstanceID = inputInstanceID + unity_BaseInstanceID;
    #endif
    }
    // The compound matrices: UNITY_MATRIX_MVP & co. (UnityShaderVariables.cginc) are computed
    // where they are used, from the instance's unity_ObjectToWorld, so there is nothing to
    // precompute; the _Instanced names are those same expressions.
    void UnitySetupCompoundMatrices() {}
    #define unity_MatrixMVP_Instanced UNITY_MATRIX_MVP
    #define unity_MatrixMV_Instanced UNITY_MATRIX_MV
    #define unity_MatrixTMV_Instanced UNITY_MATRIX_T_MV
    #define unity_MatrixITMV_Instanced UNITY_MATRIX_IT_MV

    #undef UNITY_SETUP_INSTANCE_ID
    #if defined(UNITY_PROCEDURAL_INSTANCING_ENABLED) && defined(UNITY_INSTANCING_PROCEDURAL_FUNC)
        // The program defines FUNC (any order): it computes this instance's unity_ObjectToWorld,
        // unity_WorldToObject and properties from unity_InstanceID, before anything reads them.
        void UNITY_INSTANCING_PROCEDURAL_FUNC();
        #define UNITY_SETUP_INSTANCE_ID(input) { UnitySetupInstanceID(UNITY_GET_INSTANCE_ID(input)); UNITY_INSTANCING_PROCEDURAL_FUNC(); }
    #else
        #define UNITY_SETUP_INSTANCE_ID(input) UnitySetupInstanceID(UNITY_GET_INSTANCE_ID(input))
    #endif
#endif

// The DEFAULT_ spellings Unity keeps so that a shader may redefine the plain ones.
#define DEFAULT_UNITY_SETUP_INSTANCE_ID(input) UNITY_SETUP_INSTANCE_ID(input)
#define DEFAULT_UNITY_VERTEX_OUTPUT_STEREO UNITY_VERTEX_OUTPUT_STEREO
#define DEFAULT_UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(output) UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(output)
#define DEFAULT_UNITY_TRANSFER_VERTEX_OUTPUT_STEREO(input, output) UNITY_TRANSFER_VERTEX_OUTPUT_STEREO(input, output)
#define DEFAULT_UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX(input) UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX(input)
// The eye index alone (Unity 2018.4+), for outputs that carry no render-target layer.
#if !defined(UNITY_VERTEX_OUTPUT_STEREO_EYE_INDEX)
#if defined(UNITY_STEREO_INSTANCING_ENABLED)
    #define UNITY_VERTEX_OUTPUT_STEREO_EYE_INDEX nointerpolation uint stereoTargetEyeIndex : BLENDINDICES0;
    #define UNITY_INITIALIZE_OUTPUT_STEREO_EYE_INDEX(output) (output).stereoTargetEyeIndex = unity_StereoEyeIndex
#else
    #define UNITY_VERTEX_OUTPUT_STEREO_EYE_INDEX
    #define UNITY_INITIALIZE_OUTPUT_STEREO_EYE_INDEX(output)
#endif
#endif
#define DEFAULT_UNITY_VERTEX_OUTPUT_STEREO_EYE_INDEX UNITY_VERTEX_OUTPUT_STEREO_EYE_INDEX
#define DEFAULT_UNITY_INITIALIZE_OUTPUT_STEREO_EYE_INDEX(output) UNITY_INITIALIZE_OUTPUT_STEREO_EYE_INDEX(output)

// Unity 5.6's spelling of the per-instance block, and the plain block of 2017.4+.
#define UNITY_INSTANCING_CBUFFER_START(name) UNITY_INSTANCING_BUFFER_START(name)
#define UNITY_INSTANCING_CBUFFER_END UNITY_INSTANCING_BUFFER_END(unused)
#define UNITY_INSTANCING_CBUFFER_SCOPE_BEGIN(name) CBUFFER_START(name)
#define UNITY_INSTANCING_CBUFFER_SCOPE_END CBUFFER_END
// Unity 2020.3 merges its built-in per-instance blocks; here each property is its own array.
#define UNITY_ACCESS_MERGED_INSTANCED_PROP(arr, var) UNITY_ACCESS_INSTANCED_PROP(arr, var)

#endif // VARC_INSTANCING_SETUP_INCLUDED
