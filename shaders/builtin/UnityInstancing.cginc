// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityInstancing.cginc. GPU instancing for built-in-pipeline shaders: the shared
// macros (VarcInstancing.hlsl) plus per-instance object matrices replacing unity_ObjectToWorld
// and unity_WorldToObject when INSTANCING_ON is set, procedural instancing
// (PROCEDURAL_INSTANCING_ON) and the stereo eye of STEREO_INSTANCING_ON. Written for varc.
//
// `#pragma instancing_options` reaches this file as macros the compile driver defines
// (docs/SHADER_ABI.md §3): procedural:FUNC -> UNITY_INSTANCING_PROCEDURAL_FUNC FUNC,
// maxcount:N -> UNITY_MAX_INSTANCE_COUNT N, forcemaxcount:N -> UNITY_FORCE_MAX_INSTANCE_COUNT N,
// assumeuniformscaling -> UNITY_ASSUME_UNIFORM_SCALING, nomatrices ->
// UNITY_DONT_INSTANCE_OBJECT_MATRICES, lodfade -> UNITY_INSTANCED_LOD_FADE, renderinglayer ->
// UNITY_INSTANCED_RENDERING_LAYER. Unity also instances light probes and lightmap scale/offsets
// unless told nolightprobe / nolightmap; varc's runtime batches only draws that share those
// values, so they stay per draw (as with both options) unless a program defines
// UNITY_INSTANCED_SH / UNITY_INSTANCED_LIGHTMAPSTS itself.
#ifndef UNITY_INSTANCING_INCLUDED
#define UNITY_INSTANCING_INCLUDED

#include "HLSLSupport.cginc"
#include "UnityShaderVariables.cginc"

// Surface-shader analysis only needs the declarations: one element per array.
#if defined(SHADER_TARGET_SURFACE_ANALYSIS)
#undef UNITY_FORCE_MAX_INSTANCE_COUNT
#define UNITY_FORCE_MAX_INSTANCE_COUNT 1
#endif
// Vulkan uniform blocks take any array size the options ask for.
#define UNITY_INSTANCING_SUPPORT_FLEXIBLE_ARRAY_SIZE 1

#include "VarcInstancing.hlsl"

// Which block holds unity_WorldToObjectArray: 1 (the rarely bound one) when uniform scaling lets
// normals use unity_ObjectToWorld. varc keeps both arrays in unity_Builtins0 either way.
#ifdef UNITY_ASSUME_UNIFORM_SCALING
#define UNITY_WORLDTOOBJECTARRAY_CB 1
#else
#define UNITY_WORLDTOOBJECTARRAY_CB 0
#endif
// Unity merges its built-in per-instance blocks by index; each is its own block here.
#define MERGE_UNITY_BUILTINS_INDEX(X) unity_Builtins##X
#define CALL_MERGE(X) MERGE_UNITY_BUILTINS_INDEX(X)

#if defined(UNITY_INSTANCING_ENABLED) && !defined(UNITY_DONT_INSTANCE_OBJECT_MATRICES)
    // Block UnityInstancing_unity_Builtins0 { float4x4 unity_ObjectToWorldArray[N];
    // float4x4 unity_WorldToObjectArray[N]; }, element i = instance i.
    UNITY_INSTANCING_BUFFER_START(unity_Builtins0)
        UNITY_DEFINE_INSTANCED_PROP(float4x4, unity_ObjectToWorld)
        UNITY_DEFINE_INSTANCED_PROP(float4x4, unity_WorldToObject)
    UNITY_INSTANCING_BUFFER_END(unity_Builtins0)
    // Last frame's matrices (motion vectors), in their own block to stay within 64 KiB.
    UNITY_INSTANCING_BUFFER_START(unity_Builtins3)
        UNITY_DEFINE_INSTANCED_PROP(float4x4, unity_PrevObjectToWorld)
        UNITY_DEFINE_INSTANCED_PROP(float4x4, unity_PrevWorldToObject)
    UNITY_INSTANCING_BUFFER_END(unity_Builtins3)
    #define unity_ObjectToWorld UNITY_ACCESS_INSTANCED_PROP(unity_Builtins0, unity_ObjectToWorld)
    #define unity_WorldToObject UNITY_ACCESS_INSTANCED_PROP(unity_Builtins0, unity_WorldToObject)
    #define VARC_INSTANCE_MATRICES 1
#elif defined(UNITY_PROCEDURAL_INSTANCING_ENABLED) && !defined(UNITY_DONT_INSTANCE_OBJECT_MATRICES)
    // Procedural instancing: the procedural function computes the instance's matrices by
    // assigning unity_ObjectToWorld / unity_WorldToObject, which are therefore program statics,
    // starting from the draw's own matrices.
    static float4x4 varc_ProceduralObjectToWorld = unity_ObjectToWorld;
    static float4x4 varc_ProceduralWorldToObject = unity_WorldToObject;
    #define unity_ObjectToWorld varc_ProceduralObjectToWorld
    #define unity_WorldToObject varc_ProceduralWorldToObject
    #define VARC_INSTANCE_MATRICES 1
#endif

#if defined(VARC_INSTANCE_MATRICES)
    // UnityObjectToClipPos (UnityShaderUtilities.cginc) was compiled against the plain matrix
    // before the lines above: the instanced programs use these, with the instance's matrix.
    inline float4 UnityObjectToClipPosInstanced(in float3 pos) {
        return mul(UNITY_MATRIX_VP, mul(unity_ObjectToWorld, float4(pos, 1.0)));
    }
    inline float4 UnityObjectToClipPosInstanced(float4 pos) { return UnityObjectToClipPosInstanced(pos.xyz); }
    #define UnityObjectToClipPos UnityObjectToClipPosInstanced
#endif
#if !defined(UNITY_DONT_INSTANCE_OBJECT_MATRICES)
    // No omni-directional stereo capture in varc: the ODS transform is the plain one (as in
    // UnityShaderUtilities.cginc), with the instance's matrix.
    inline float4 UnityObjectToClipPosODSInstanced(float3 inPos) { return UnityObjectToClipPos(inPos); }
    #define UnityObjectToClipPosODS UnityObjectToClipPosODSInstanced
#endif

#if defined(UNITY_INSTANCING_ENABLED)
    // Built-in per-draw values Unity can instance, each under the condition that makes it vary
    // per instance (see the options above). Block UnityInstancing_unity_Builtins1 holds LOD
    // fade, rendering layer and lightmap scale/offsets; unity_Builtins2 the SH probes.
    #if defined(UNITY_INSTANCED_LOD_FADE) && (defined(LOD_FADE_PERCENTAGE) || defined(LOD_FADE_CROSSFADE))
        #define UNITY_USE_LODFADE_ARRAY 1
        #define UNITY_USE_LODFADEARRAY 1
    #endif
    #if defined(UNITY_INSTANCED_RENDERING_LAYER)
        #define UNITY_USE_RENDERINGLAYER_ARRAY 1
    #endif
    #if defined(UNITY_INSTANCED_LIGHTMAPSTS) && defined(LIGHTMAP_ON)
        #define UNITY_USE_LIGHTMAPST_ARRAY 1
    #endif
    #if defined(UNITY_INSTANCED_LIGHTMAPSTS) && defined(DYNAMICLIGHTMAP_ON)
        #define UNITY_USE_DYNAMICLIGHTMAPST_ARRAY 1
    #endif
    // UNITY_SHOULD_SAMPLE_SH (UnityCG.cginc): no lightmap of either kind.
    #if defined(UNITY_INSTANCED_SH) && !defined(LIGHTMAP_ON) && !defined(DYNAMICLIGHTMAP_ON)
        #define UNITY_USE_SHCOEFFS_ARRAYS 1
    #endif
    #if defined(UNITY_INSTANCED_SH) && defined(UNITY_PASS_DEFERRED) && defined(SHADOWS_SHADOWMASK) && (UNITY_ALLOWED_MRT_COUNT > 4)
        #define UNITY_USE_PROBESOCCLUSION_ARRAY 1
    #endif

    #if defined(UNITY_USE_LODFADE_ARRAY) || defined(UNITY_USE_RENDERINGLAYER_ARRAY) || defined(UNITY_USE_LIGHTMAPST_ARRAY) || defined(UNITY_USE_DYNAMICLIGHTMAPST_ARRAY)
    UNITY_INSTANCING_BUFFER_START(unity_Builtins1)
        #if defined(UNITY_USE_LODFADE_ARRAY)
        UNITY_DEFINE_INSTANCED_PROP(float2, unity_LODFade)
        #endif
        #if defined(UNITY_USE_RENDERINGLAYER_ARRAY)
        UNITY_DEFINE_INSTANCED_PROP(float, unity_RenderingLayer)
        #endif
        #if defined(UNITY_USE_LIGHTMAPST_ARRAY)
        UNITY_DEFINE_INSTANCED_PROP(float4, unity_LightmapST)
        #endif
        #if defined(UNITY_USE_DYNAMICLIGHTMAPST_ARRAY)
        UNITY_DEFINE_INSTANCED_PROP(float4, unity_DynamicLightmapST)
        #endif
    UNITY_INSTANCING_BUFFER_END(unity_Builtins1)
    #endif
    #if defined(UNITY_USE_SHCOEFFS_ARRAYS) || defined(UNITY_USE_PROBESOCCLUSION_ARRAY)
    UNITY_INSTANCING_BUFFER_START(unity_Builtins2)
        #if defined(UNITY_USE_SHCOEFFS_ARRAYS)
        UNITY_DEFINE_INSTANCED_PROP(half4, unity_SHAr)
        UNITY_DEFINE_INSTANCED_PROP(half4, unity_SHAg)
        UNITY_DEFINE_INSTANCED_PROP(half4, unity_SHAb)
        UNITY_DEFINE_INSTANCED_PROP(half4, unity_SHBr)
        UNITY_DEFINE_INSTANCED_PROP(half4, unity_SHBg)
        UNITY_DEFINE_INSTANCED_PROP(half4, unity_SHBb)
        UNITY_DEFINE_INSTANCED_PROP(half4, unity_SHC)
        #endif
        #if defined(UNITY_USE_PROBESOCCLUSION_ARRAY)
        UNITY_DEFINE_INSTANCED_PROP(half4, unity_ProbesOcclusion)
        #endif
    UNITY_INSTANCING_BUFFER_END(unity_Builtins2)
    #endif

    // The per-draw names read the instance's element from here on.
    #if defined(UNITY_USE_LODFADE_ARRAY)
        #define unity_LODFade UNITY_ACCESS_INSTANCED_PROP(unity_Builtins1, unity_LODFade).xyxx
    #endif
    #if defined(UNITY_USE_RENDERINGLAYER_ARRAY)
        #define unity_RenderingLayer UNITY_ACCESS_INSTANCED_PROP(unity_Builtins1, unity_RenderingLayer).xxxx
    #endif
    #if defined(UNITY_USE_LIGHTMAPST_ARRAY)
        #define unity_LightmapST UNITY_ACCESS_INSTANCED_PROP(unity_Builtins1, unity_LightmapST)
    #endif
    #if defined(UNITY_USE_DYNAMICLIGHTMAPST_ARRAY)
        #define unity_DynamicLightmapST UNITY_ACCESS_INSTANCED_PROP(unity_Builtins1, unity_DynamicLightmapST)
    #endif
    #if defined(UNITY_USE_SHCOEFFS_ARRAYS)
        #define unity_SHAr UNITY_ACCESS_INSTANCED_PROP(unity_Builtins2, unity_SHAr)
        #define unity_SHAg UNITY_ACCESS_INSTANCED_PROP(unity_Builtins2, unity_SHAg)
        #define unity_SHAb UNITY_ACCESS_INSTANCED_PROP(unity_Builtins2, unity_SHAb)
        #define unity_SHBr UNITY_ACCESS_INSTANCED_PROP(unity_Builtins2, unity_SHBr)
        #define unity_SHBg UNITY_ACCESS_INSTANCED_PROP(unity_Builtins2, unity_SHBg)
        #define unity_SHBb UNITY_ACCESS_INSTANCED_PROP(unity_Builtins2, unity_SHBb)
        #define unity_SHC UNITY_ACCESS_INSTANCED_PROP(unity_Builtins2, unity_SHC)
    #endif
    #if defined(UNITY_USE_PROBESOCCLUSION_ARRAY)
        #define unity_ProbesOcclusion UNITY_ACCESS_INSTANCED_PROP(unity_Builtins2, unity_ProbesOcclusion)
    #endif
#endif

#include "VarcInstancingSetup.cginc"

#endif // UNITY_INSTANCING_INCLUDED
