// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityShaderVariables.cginc. Declares Unity's built-in shader variables, grouped
// into uniform blocks by update frequency, plus the UNITY_MATRIX_* and legacy-name macros.
// The runtime fills every member BY NAME through the pack's reflection; docs/SHADER_ABI.md gives
// each member's meaning, units and space. Written for varc; not derived from Unity's file.
#ifndef UNITY_SHADER_VARIABLES_INCLUDED
#define UNITY_SHADER_VARIABLES_INCLUDED

#include "HLSLSupport.cginc"

// ---------------------------------------------------------------------------------------------
// Per frame: time, ambient, fog.
// ---------------------------------------------------------------------------------------------
CBUFFER_START(UnityPerFrame)
    float4 _Time;                       // (t/20, t, 2t, 3t), t in seconds
    float4 _SinTime;                    // (sin(t/8), sin(t/4), sin(t/2), sin(t))
    float4 _CosTime;                    // (cos(t/8), cos(t/4), cos(t/2), cos(t))
    float4 unity_DeltaTime;             // (dt, 1/dt, smoothDt, 1/smoothDt)
    half4 glstate_lightmodel_ambient;   // flat ambient colour (linear RGB, a = 1)
    half4 unity_AmbientSky;             // trilight ambient: sky
    half4 unity_AmbientEquator;         // trilight ambient: equator
    half4 unity_AmbientGround;          // trilight ambient: ground
    half4 unity_IndirectSpecColor;      // average reflection-probe colour
    half4 unity_FogColor;               // fog colour
    float4 unity_FogParams;             // (density/sqrt(ln2), density/ln2, -1/(end-start), end/(end-start))
CBUFFER_END

// ---------------------------------------------------------------------------------------------
// Per camera.
// ---------------------------------------------------------------------------------------------
CBUFFER_START(UnityPerCamera)
    float3 _WorldSpaceCameraPos;        // camera position, world space
    float4 _ProjectionParams;           // (1, near, far, 1/far)
    float4 _ScreenParams;               // (width, height, 1+1/width, 1+1/height) in pixels
    float4 _ZBufferParams;              // (1-far/near, far/near, x/far, y/far)
    float4 unity_OrthoParams;           // (ortho half-width, ortho half-height, 0, 1 if ortho else 0)
    float4 unity_CameraWorldClipPlanes[6]; // left, right, bottom, top, near, far (world, normal inward)
    float4x4 unity_MatrixV;             // world -> view (right-handed, camera looks down -z)
    float4x4 unity_MatrixInvV;          // view -> world
    float4x4 glstate_matrix_projection; // view -> Vulkan clip (y down, z in [0,w])
    float4x4 unity_MatrixVP;            // glstate_matrix_projection * unity_MatrixV
    float4x4 unity_CameraProjection;    // the camera's own GL-style projection (no Vulkan fix-up)
    float4x4 unity_CameraInvProjection; // inverse of unity_CameraProjection
    float4x4 unity_WorldToCamera;       // world -> camera object space (+z forward)
    float4x4 unity_CameraToWorld;       // camera object space (+z forward) -> world
CBUFFER_END

// ---------------------------------------------------------------------------------------------
// Per draw: the object's transforms.
// ---------------------------------------------------------------------------------------------
CBUFFER_START(UnityPerDraw)
    float4x4 unity_ObjectToWorld;
    float4x4 unity_WorldToObject;
    float4 unity_LODFade;               // (fade, fade quantized to 16 levels, 0, 0)
    float4 unity_WorldTransformParams;  // w = -1 if the object matrix mirrors, else 1
CBUFFER_END
// The rendering layer mask (Unity 2018.4+), x = asfloat(mask); varc's runtime leaves it 0. Its
// own block, so that programs that do not read it keep UnityPerDraw's layout.
CBUFFER_START(UnityRenderingLayer)
    float4 unity_RenderingLayer;
CBUFFER_END

// ---------------------------------------------------------------------------------------------
// Per draw, forward base / deferred G-buffer: light probe SH (packing: docs/SHADER_ABI.md §4.4).
// ---------------------------------------------------------------------------------------------
CBUFFER_START(UnityProbes)
    half4 unity_SHAr;
    half4 unity_SHAg;
    half4 unity_SHAb;
    half4 unity_SHBr;
    half4 unity_SHBg;
    half4 unity_SHBb;
    half4 unity_SHC;
    half4 unity_ProbesOcclusion;
CBUFFER_END

// ---------------------------------------------------------------------------------------------
// Per draw, forward base: the four per-vertex point lights (docs/LIGHTING.md §5) and the
// eight-light arrays of the legacy Vertex pass (view space).
// ---------------------------------------------------------------------------------------------
CBUFFER_START(UnityVertexLights)
    float4 unity_4LightPosX0;           // world x of vertex lights 0..3
    float4 unity_4LightPosY0;           // world y
    float4 unity_4LightPosZ0;           // world z
    half4 unity_4LightAtten0;           // 25 / range^2 per light (0 if unused)
    half4 unity_LightColor[8];          // colour * intensity (linear); [0..3] = the vertex lights
    float4 unity_LightPosition[8];      // view space: (pos,1) or (-dir,0)
    half4 unity_LightAtten[8];          // (cos(spot/2) or -1, 1/(cos(spot/4)-cos(spot/2)) or 1, 25/range^2, range^2)
    float4 unity_SpotDirection[8];      // view space spot direction (0,0,1,0 for non-spots)
CBUFFER_END

// ---------------------------------------------------------------------------------------------
// Per light (one ForwardAdd draw per light; the main directional light in ForwardBase).
// ---------------------------------------------------------------------------------------------
CBUFFER_START(UnityLighting)
    float4 _WorldSpaceLightPos0;        // directional: (direction towards the light, 0); else (position, 1)
    half4 _LightColor0;                 // colour * intensity (linear)
    float4 _LightPositionRange;         // (position, 1/range)
    float4 _LightProjectionParams;      // reserved, (0,0,0,1)
    float4x4 unity_WorldToLight;        // world -> light space, range-normalised (SHADER_ABI.md §5)
    float4 unity_OcclusionMaskSelector; // one-hot shadowmask channel of this light
CBUFFER_END

// ---------------------------------------------------------------------------------------------
// Per light: real-time shadows.
// ---------------------------------------------------------------------------------------------
CBUFFER_START(UnityShadows)
    float4 unity_ShadowSplitSpheres[4]; // cascade culling spheres (center, radius)
    float4 unity_ShadowSplitSqRadii;    // squared radii of the four spheres
    float4 unity_LightShadowBias;       // (depth bias, clamp flag, normal bias, 0) for casters
    float4 _LightSplitsNear;
    float4 _LightSplitsFar;
    float4x4 unity_WorldToShadow[4];    // world -> shadow-map (u, v, depth, 1); [0] for spot lights
    half4 _LightShadowData;             // (1 - strength, 0, fade scale, fade offset)
    float4 unity_ShadowFadeCenterAndType; // (fade sphere center, 1 = sphere distance / 0 = view depth)
    float4 _ShadowMapTexture_TexelSize; // (1/width, 1/height, width, height) of _ShadowMapTexture
CBUFFER_END

// ---------------------------------------------------------------------------------------------
// Matrix macros (Unity 5.4+ names) and the legacy names older shaders use.
// ---------------------------------------------------------------------------------------------
#define UNITY_MATRIX_M unity_ObjectToWorld
#define UNITY_MATRIX_I_M unity_WorldToObject
#define UNITY_MATRIX_V unity_MatrixV
#define UNITY_MATRIX_I_V unity_MatrixInvV
#define UNITY_MATRIX_P glstate_matrix_projection
#define UNITY_MATRIX_VP unity_MatrixVP
#define UNITY_MATRIX_MVP mul(unity_MatrixVP, unity_ObjectToWorld)
#define UNITY_MATRIX_MV mul(unity_MatrixV, unity_ObjectToWorld)
#define UNITY_MATRIX_T_MV transpose(UNITY_MATRIX_MV)
#define UNITY_MATRIX_IT_MV transpose(mul(unity_WorldToObject, unity_MatrixInvV))

#define glstate_matrix_mvp UNITY_MATRIX_MVP
#define glstate_matrix_modelview0 UNITY_MATRIX_MV
#define glstate_matrix_invtrans_modelview0 UNITY_MATRIX_IT_MV
#define _Object2World unity_ObjectToWorld
#define _World2Object unity_WorldToObject
#define _LightMatrix0 unity_WorldToLight
#define unity_World2Shadow unity_WorldToShadow
#define _CameraToWorld unity_CameraToWorld
#define _WorldToCamera unity_WorldToCamera

// varc stores the full ambient colour in glstate_lightmodel_ambient (SHADER_ABI.md §4.1).
#define UNITY_LIGHTMODEL_AMBIENT (glstate_lightmodel_ambient)

// =============================================================================================
// Additions for third-party shaders. Each group is its own block, so a program that uses none of
// its names keeps exactly the blocks above (unused declarations are pruned).
// =============================================================================================

// ---------------------------------------------------------------------------------------------
// Reflection probes (SHADER_ABI.md §4.13): the two probes blended for this draw. BoxMin.w is
// probe 0's blend weight (1 with a single probe); ProbePosition.w > 0 turns on box projection.
// ---------------------------------------------------------------------------------------------
UNITY_DECLARE_TEXCUBE(unity_SpecCube0);
UNITY_DECLARE_TEXCUBE_NOSAMPLER(unity_SpecCube1);
CBUFFER_START(UnityReflectionProbes)
    float4 unity_SpecCube0_BoxMax;       // box max (world), w unused
    float4 unity_SpecCube0_BoxMin;       // box min (world), w = blend weight of probe 0
    float4 unity_SpecCube0_ProbePosition; // probe centre (world), w = 1 box projection, 0 infinite
    half4 unity_SpecCube0_HDR;           // DecodeHDR instructions, (1, 1, 0, 0) for float cubes
    float4 unity_SpecCube1_BoxMax;
    float4 unity_SpecCube1_BoxMin;
    float4 unity_SpecCube1_ProbePosition;
    half4 unity_SpecCube1_HDR;
CBUFFER_END
// Reflection-probe features the GI code may use (Unity sets these per graphics tier).
#ifndef UNITY_SPECCUBE_BOX_PROJECTION
#define UNITY_SPECCUBE_BOX_PROJECTION 1
#endif
#ifndef UNITY_SPECCUBE_BLENDING
#define UNITY_SPECCUBE_BLENDING 1
#endif

// ---------------------------------------------------------------------------------------------
// Lightmaps (SHADER_ABI.md §4.13): baked (LIGHTMAP_ON) and realtime (DYNAMICLIGHTMAP_ON) maps,
// their directional companions, the baked shadow mask, and their uv scale/offsets.
// ---------------------------------------------------------------------------------------------
UNITY_DECLARE_TEX2D(unity_Lightmap);
UNITY_DECLARE_TEX2D_NOSAMPLER(unity_LightmapInd);
UNITY_DECLARE_TEX2D(unity_ShadowMask);
UNITY_DECLARE_TEX2D(unity_DynamicLightmap);
UNITY_DECLARE_TEX2D_NOSAMPLER(unity_DynamicDirectionality);
UNITY_DECLARE_TEX2D_NOSAMPLER(unity_DynamicNormal);
CBUFFER_START(UnityLightmaps)
    float4 unity_LightmapST;             // uv1 * xy + zw -> unity_Lightmap uv
    float4 unity_DynamicLightmapST;      // uv2 * xy + zw -> unity_DynamicLightmap uv
    half4 unity_Lightmap_HDR;            // decode instructions (varc: (1, 1, 0, 0), unused)
    half4 unity_DynamicLightmap_HDR;
CBUFFER_END

// ---------------------------------------------------------------------------------------------
// Stereo: varc renders one eye per pass; the eye index is the constant 0, except in stereo
// instancing variants, where UnitySetupInstanceID (UnityInstancing.cginc) sets it per instance.
// ---------------------------------------------------------------------------------------------
#if defined(UNITY_STEREO_INSTANCING_ENABLED)
#ifndef VARC_STEREO_EYE_INDEX_DECLARED
#define VARC_STEREO_EYE_INDEX_DECLARED
static uint unity_StereoEyeIndex;
#endif
#else
static const int unity_StereoEyeIndex = 0;
#endif

// ---------------------------------------------------------------------------------------------
// More legacy names.
// ---------------------------------------------------------------------------------------------
#define unity_MatrixMVP UNITY_MATRIX_MVP
#define unity_MatrixMV UNITY_MATRIX_MV
#define unity_MatrixTMV UNITY_MATRIX_T_MV
#define unity_MatrixITMV UNITY_MATRIX_IT_MV
// Unity 4 names of the first four vertex-light colours.
#define unity_LightColor0 unity_LightColor[0]
#define unity_LightColor1 unity_LightColor[1]
#define unity_LightColor2 unity_LightColor[2]
#define unity_LightColor3 unity_LightColor[3]

// ---------------------------------------------------------------------------------------------
// More of Unity's variables (issue #27, docs/BUILTIN_API.md).
// ---------------------------------------------------------------------------------------------
// Set when the variant renders a directional light (forward passes' light keywords).
#if defined(DIRECTIONAL) || defined(DIRECTIONAL_COOKIE)
#define USING_DIRECTIONAL_LIGHT
#endif
// Fixed-function texture matrices: the identity since Unity 5.
#define UNITY_MATRIX_TEXTURE0 float4x4(1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1)
#define UNITY_MATRIX_TEXTURE1 UNITY_MATRIX_TEXTURE0
#define UNITY_MATRIX_TEXTURE2 UNITY_MATRIX_TEXTURE0
#define UNITY_MATRIX_TEXTURE3 UNITY_MATRIX_TEXTURE0
#define glstate_matrix_transpose_modelview0 UNITY_MATRIX_T_MV

// Light probe proxy volumes: varc has none, so UNITY_LIGHT_PROBE_PROXY_VOLUME is 0 (Unity's value
// on platforms without them: code tests it with #if) and the runtime leaves this block zero
// (unity_ProbeVolumeParams.x = 0: "use the SH probes").
#ifndef UNITY_LIGHT_PROBE_PROXY_VOLUME
#define UNITY_LIGHT_PROBE_PROXY_VOLUME 0
#endif
// Declared so that shaders sampling a volume where Unity would still compile.
UNITY_DECLARE_TEX3D_FLOAT(unity_ProbeVolumeSH);
CBUFFER_START(UnityProbeVolume)
    float4 unity_ProbeVolumeParams;       // (enabled, 1 = global space, texel size x, 0)
    float4x4 unity_ProbeVolumeWorldToObject;
    float3 unity_ProbeVolumeSizeInv;
    float3 unity_ProbeVolumeMin;
CBUFFER_END

// The legacy shadow colour of Unity 4 (unused by the built-in pipeline since; zero here).
CBUFFER_START(UnityLegacyShadowColor)
    fixed4 unity_ShadowColor;
CBUFFER_END

// Single-pass stereo matrices, declared where Unity declares them (USING_STEREO_MATRICES: a
// variant with UNITY_SINGLE_PASS_STEREO or stereo instancing/multiview). varc renders one eye
// per pass and its runtime does not fill this block: such variants compile, with eye 0's values
// expected in the mono variables above.
#if defined(UNITY_SINGLE_PASS_STEREO) || defined(UNITY_STEREO_INSTANCING_ENABLED) || defined(UNITY_STEREO_MULTIVIEW_ENABLED)
#define USING_STEREO_MATRICES
#endif
#if defined(USING_STEREO_MATRICES)
CBUFFER_START(UnityStereoGlobals)
    float4x4 unity_StereoMatrixP[2];
    float4x4 unity_StereoMatrixV[2];
    float4x4 unity_StereoMatrixInvV[2];
    float4x4 unity_StereoMatrixVP[2];
    float4x4 unity_StereoCameraProjection[2];
    float4x4 unity_StereoCameraInvProjection[2];
    float4x4 unity_StereoWorldToCamera[2];
    float4x4 unity_StereoCameraToWorld[2];
    float3 unity_StereoWorldSpaceCameraPos[2];
    float4 unity_StereoScaleOffset[2];
CBUFFER_END
CBUFFER_START(UnityStereoEyeIndices)
    float4 unity_StereoEyeIndices[2];
CBUFFER_END
CBUFFER_START(UnityStereoSeparation)
    float4 unity_HalfStereoSeparation;   // Unity 2018.4+: half the eye separation, for effects
CBUFFER_END
#endif

// UnityObjectToClipPos for programs that include nothing else (as in Unity).
#include "UnityShaderUtilities.cginc"

#endif // UNITY_SHADER_VARIABLES_INCLUDED
