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

// Instancing needs `#pragma target 3.5` or higher, as in Unity; then INSTANCING_ON (from
// `#pragma multi_compile_instancing`) or PROCEDURAL_INSTANCING_ON turns it on.
#if defined(SHADER_TARGET) && SHADER_TARGET >= 35 && !defined(UNITY_SUPPORT_INSTANCING)
#define UNITY_SUPPORT_INSTANCING 1
#endif
#if defined(UNITY_SUPPORT_INSTANCING) && (defined(INSTANCING_ON) || defined(PROCEDURAL_INSTANCING_ON))
#define UNITY_INSTANCING_ENABLED 1
#endif

// Elements per instanced array; `#pragma instancing_options maxcount:N` maps to this define.
// 500 instances of two float4x4 = 64000 bytes, within a 64 KiB maxUniformBufferRange.
#ifndef UNITY_MAX_INSTANCE_COUNT
#define UNITY_MAX_INSTANCE_COUNT 500
#endif
#ifndef UNITY_INSTANCED_ARRAY_SIZE
#define UNITY_INSTANCED_ARRAY_SIZE UNITY_MAX_INSTANCE_COUNT
#endif

#if defined(UNITY_INSTANCING_ENABLED)
    // SV_InstanceID becomes gl_InstanceIndex on vertex input (it includes firstInstance, so the
    // runtime draws instanced batches with firstInstance = 0) and a flat varying elsewhere.
    #define UNITY_VERTEX_INPUT_INSTANCE_ID uint instanceID : SV_InstanceID;
    #define UNITY_GET_INSTANCE_ID(input) (input).instanceID
    static uint unity_InstanceID;
    #define UNITY_SETUP_INSTANCE_ID(input) unity_InstanceID = UNITY_GET_INSTANCE_ID(input)
    #define UNITY_TRANSFER_INSTANCE_ID(input, output) (output).instanceID = UNITY_GET_INSTANCE_ID(input)

    // One uniform block per buffer, one array per property (element i = instance i):
    // UnityInstancing_<buf> { <type> <prop>Array[UNITY_INSTANCED_ARRAY_SIZE]; ... }
    // Plain top-level arrays keep the block reflectable member by member (SHADER_ABI.md §4.10).
    #define UNITY_INSTANCING_BUFFER_START(buf) CBUFFER_START(UnityInstancing_##buf)
    #define UNITY_INSTANCING_BUFFER_END(arr) CBUFFER_END
    #define UNITY_DEFINE_INSTANCED_PROP(type, var) type var##Array[UNITY_INSTANCED_ARRAY_SIZE];
    #define UNITY_ACCESS_INSTANCED_PROP(arr, var) var##Array[unity_InstanceID]
#else
    #define UNITY_VERTEX_INPUT_INSTANCE_ID
    #define UNITY_GET_INSTANCE_ID(input) 0
    #define UNITY_SETUP_INSTANCE_ID(input)
    #define UNITY_TRANSFER_INSTANCE_ID(input, output)

    // Not instanced: the properties are plain members of the block UnityInstancing_<name>.
    #define UNITY_INSTANCING_BUFFER_START(buf) CBUFFER_START(UnityInstancing_##buf)
    #define UNITY_INSTANCING_BUFFER_END(arr) CBUFFER_END
    #define UNITY_DEFINE_INSTANCED_PROP(type, var) type var;
    #define UNITY_ACCESS_INSTANCED_PROP(arr, var) var
#endif

// Single-pass stereo is not supported by varc: the stereo macros expand to nothing.
#define UNITY_VERTEX_OUTPUT_STEREO
#define UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(output)
#define UNITY_TRANSFER_VERTEX_OUTPUT_STEREO(input, output)
#define UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX(input)
#define DEFAULT_UNITY_VERTEX_INPUT_INSTANCE_ID UNITY_VERTEX_INPUT_INSTANCE_ID

#endif // VARC_INSTANCING_INCLUDED
