// SPDX-License-Identifier: Apache-2.0
// varc built-in: VarcInstancing.hlsl. The GPU-instancing macros shared by UnityInstancing.cginc
// (built-in pipeline) and the SRP core's UnityInstancing.hlsl: instance ID plumbing and
// per-instance property blocks. Written for varc from Unity's documented macro contract.
#ifndef VARC_INSTANCING_INCLUDED
#define VARC_INSTANCING_INCLUDED

#ifndef CBUFFER_START
#define CBUFFER_START(name) cbuffer name {
#define CBUFFER_END };
#endif

// Instancing needs `#pragma target 3.5` or higher, as in Unity. INSTANCING_ON (from `#pragma
// multi_compile_instancing`) turns on per-instance arrays; PROCEDURAL_INSTANCING_ON (the extra
// variant `#pragma instancing_options procedural:FUNC` adds) turns on procedural instancing,
// where the program computes each instance's data in FUNC (UnityInstancing.cginc);
// STEREO_INSTANCING_ON draws both eyes of single-pass stereo as instance pairs.
#if defined(SHADER_TARGET) && SHADER_TARGET >= 35 && !defined(UNITY_SUPPORT_INSTANCING)
#define UNITY_SUPPORT_INSTANCING 1
#endif
#if defined(SHADER_TARGET) && SHADER_TARGET >= 35 && !defined(UNITY_SUPPORT_STEREO_INSTANCING)
#define UNITY_SUPPORT_STEREO_INSTANCING 1
#endif
#if defined(UNITY_SUPPORT_INSTANCING) && defined(INSTANCING_ON)
#define UNITY_INSTANCING_ENABLED 1
#endif
#if defined(UNITY_SUPPORT_INSTANCING) && defined(PROCEDURAL_INSTANCING_ON)
#define UNITY_PROCEDURAL_INSTANCING_ENABLED 1
#endif
#if defined(UNITY_SUPPORT_STEREO_INSTANCING) && defined(STEREO_INSTANCING_ON) && !defined(UNITY_STEREO_INSTANCING_ENABLED)
#define UNITY_STEREO_INSTANCING_ENABLED 1
#endif
#if defined(UNITY_INSTANCING_ENABLED) || defined(UNITY_PROCEDURAL_INSTANCING_ENABLED) || defined(UNITY_STEREO_INSTANCING_ENABLED)
#define VARC_ANY_INSTANCING 1
#endif

// Elements per instanced array: `#pragma instancing_options maxcount:N` / `forcemaxcount:N`
// define UNITY_MAX_INSTANCE_COUNT / UNITY_FORCE_MAX_INSTANCE_COUNT (compile driver). Vulkan
// uniform blocks have a fixed size, so the array always has the requested count (Unity calls
// this the flexible size of D3D11/GL/Vulkan). 500 instances of two float4x4 = 64000 bytes,
// within a 64 KiB maxUniformBufferRange.
#ifndef UNITY_MAX_INSTANCE_COUNT
#define UNITY_MAX_INSTANCE_COUNT 500
#endif
#ifndef UNITY_INSTANCED_ARRAY_SIZE
#if defined(UNITY_FORCE_MAX_INSTANCE_COUNT)
#define UNITY_INSTANCED_ARRAY_SIZE UNITY_FORCE_MAX_INSTANCE_COUNT
#else
#define UNITY_INSTANCED_ARRAY_SIZE UNITY_MAX_INSTANCE_COUNT
#endif
#endif

#if defined(VARC_ANY_INSTANCING)
    // SV_InstanceID becomes gl_InstanceIndex on vertex input (it includes firstInstance, so the
    // runtime draws instanced batches with firstInstance = 0) and a flat varying elsewhere.
    #define UNITY_VERTEX_INPUT_INSTANCE_ID uint instanceID : SV_InstanceID;
    #define UNITY_GET_INSTANCE_ID(input) (input).instanceID
    static uint unity_InstanceID;
    #define UNITY_TRANSFER_INSTANCE_ID(input, output) (output).instanceID = UNITY_GET_INSTANCE_ID(input)
#else
    #define UNITY_VERTEX_INPUT_INSTANCE_ID
    #define UNITY_GET_INSTANCE_ID(input) 0
    #define UNITY_TRANSFER_INSTANCE_ID(input, output)
#endif
// UnityInstancing.cginc replaces this with UnitySetupInstanceID (base instance, stereo eye and
// the procedural function); the SRP core's file keeps the plain assignment.
#if defined(VARC_ANY_INSTANCING)
    #define UNITY_SETUP_INSTANCE_ID(input) unity_InstanceID = UNITY_GET_INSTANCE_ID(input)
#else
    #define UNITY_SETUP_INSTANCE_ID(input)
#endif

#if defined(UNITY_INSTANCING_ENABLED)
    // One uniform block per buffer, one array per property (element i = instance i):
    // UnityInstancing_<buf> { <type> <prop>Array[UNITY_INSTANCED_ARRAY_SIZE]; ... }
    // Plain top-level arrays keep the block reflectable member by member (SHADER_ABI.md §4.10).
    #define UNITY_INSTANCING_BUFFER_START(buf) CBUFFER_START(UnityInstancing_##buf)
    #define UNITY_INSTANCING_BUFFER_END(arr) CBUFFER_END
    #define UNITY_DEFINE_INSTANCED_PROP(type, var) type var##Array[UNITY_INSTANCED_ARRAY_SIZE];
    #define UNITY_ACCESS_INSTANCED_PROP(arr, var) var##Array[unity_InstanceID]
#elif defined(UNITY_PROCEDURAL_INSTANCING_ENABLED)
    // Procedural instancing: the properties are statics the procedural function may write
    // (no block: a program-private value, zero until written).
    #define UNITY_INSTANCING_BUFFER_START(buf)
    #define UNITY_INSTANCING_BUFFER_END(arr)
    #define UNITY_DEFINE_INSTANCED_PROP(type, var) static type var;
    #define UNITY_ACCESS_INSTANCED_PROP(arr, var) var
#else
    // Not instanced: the properties are plain members of the block UnityInstancing_<name>.
    #define UNITY_INSTANCING_BUFFER_START(buf) CBUFFER_START(UnityInstancing_##buf)
    #define UNITY_INSTANCING_BUFFER_END(arr) CBUFFER_END
    #define UNITY_DEFINE_INSTANCED_PROP(type, var) type var;
    #define UNITY_ACCESS_INSTANCED_PROP(arr, var) var
#endif

#if defined(UNITY_STEREO_INSTANCING_ENABLED)
    #ifndef VARC_STEREO_EYE_INDEX_DECLARED
    #define VARC_STEREO_EYE_INDEX_DECLARED
    static uint unity_StereoEyeIndex;
    #endif
    // The eye travels to later stages as a flat varying and selects the target layer (one
    // layer per eye, SV_RenderTargetArrayIndex).
    #define UNITY_VERTEX_OUTPUT_STEREO uint stereoTargetEyeIndexSV : SV_RenderTargetArrayIndex; nointerpolation uint stereoTargetEyeIndex : BLENDINDICES0;
    #define UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(output) (output).stereoTargetEyeIndexSV = unity_StereoEyeIndex; (output).stereoTargetEyeIndex = unity_StereoEyeIndex
    #define UNITY_TRANSFER_VERTEX_OUTPUT_STEREO(input, output) (output).stereoTargetEyeIndexSV = (input).stereoTargetEyeIndexSV; (output).stereoTargetEyeIndex = (input).stereoTargetEyeIndex
    // For the stages after the vertex stage (whose eye UnitySetupInstanceID sets); no stage test
    // here, so that every program's stages still preprocess alike.
    #define UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX(input) unity_StereoEyeIndex = (input).stereoTargetEyeIndex
#else
    // One eye per pass: the stereo macros expand to nothing.
    #define UNITY_VERTEX_OUTPUT_STEREO
    #define UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(output)
    #define UNITY_TRANSFER_VERTEX_OUTPUT_STEREO(input, output)
    #define UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX(input)
#endif
#define DEFAULT_UNITY_VERTEX_INPUT_INSTANCE_ID UNITY_VERTEX_INPUT_INSTANCE_ID

#endif // VARC_INSTANCING_INCLUDED
