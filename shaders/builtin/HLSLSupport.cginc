// SPDX-License-Identifier: Apache-2.0
// varc built-in: HLSLSupport.cginc. Portability layer for CG/HLSL programs compiled by glslang's
// HLSL front end (DX9-compatible mode) to Vulkan SPIR-V: Unity's precision types, sampler
// aliases, CBUFFER/branch macros, depth and shadow-map declarations. Written for varc from the
// documented behaviour (docs/SHADER_ABI.md), not derived from Unity's file.
#ifndef HLSL_SUPPORT_INCLUDED
#define HLSL_SUPPORT_INCLUDED

// ---------------------------------------------------------------------------------------------
// Platform facts. The compile driver defines SHADER_API_VULKAN, SHADER_TARGET, UNITY_VERSION,
// UNITY_PASS_*, SHADER_STAGE_* and the variant's keywords before this file.
// ---------------------------------------------------------------------------------------------
#ifndef SHADER_TARGET
#define SHADER_TARGET 25
#endif
#define UNITY_COMPILER_HLSL 1
#define UNITY_COMPILER_VARC_GLSLANG 1
// Render-target row 0 is the top of the image (Vulkan); see docs/SHADER_ABI.md §2.
#define UNITY_UV_STARTS_AT_TOP 1
// Depth is NOT reversed: 0 at the near plane, 1 at the far plane (Vulkan [0,1] clip depth).
#define UNITY_NEAR_CLIP_VALUE (0.0)
#define UNITY_RAW_FAR_CLIP_VALUE (1.0)
// Normal maps are plain RGB (xyz*0.5+0.5), not DXT5nm-swizzled.
#define UNITY_NO_DXT5nm 1
#define UNITY_ALLOWED_MRT_COUNT 8
// Vulkan has hull and domain stages (a program still needs `#pragma target 4.6` to use them).
#define UNITY_CAN_COMPILE_TESSELLATION 1
#define UNITY_SUPPORT_DEPTH_FETCH 1
#define UNITY_SAMPLE_FULL_SH_PER_PIXEL 0
// The falloff lookup stores attenuation in the red channel (docs/LIGHTING.md §4).
#define UNITY_ATTEN_CHANNEL r
// Vulkan desktop targets branch dynamically and coherently at shader model 3.0 and up.
#if SHADER_TARGET >= 30
#define UNITY_FAST_COHERENT_DYNAMIC_BRANCHING 1
#endif

// Stereo. Unity defines UNITY_STEREO_INSTANCING_ENABLED for Vulkan variants with
// STEREO_INSTANCING_ON (UnityInstancing.cginc gives such variants the eye index; screen-space
// textures become arrays of one slice per eye); multiview is a GL/GLES path, never on Vulkan.
#if defined(STEREO_INSTANCING_ON) && SHADER_TARGET >= 35
#define UNITY_STEREO_INSTANCING_ENABLED 1
#endif
#if defined(STEREO_MULTIVIEW_ON) && (defined(SHADER_API_GLES3) || defined(SHADER_API_GLCORE))
#define UNITY_STEREO_MULTIVIEW_ENABLED 1
#endif
// (Unity declares these in the vertex stage only; naming the stage macro here would make every
// program's stages preprocess apart, so they are declared in every stage of a multiview variant.)
#if defined(UNITY_STEREO_MULTIVIEW_ENABLED)
#define UNITY_DECLARE_MULTIVIEW(number_of_views) GLOBAL_CBUFFER_START(OVR_multiview) uint gl_ViewID; uint numViews_##number_of_views; GLOBAL_CBUFFER_END
#define UNITY_VIEWID gl_ViewID
#endif

// ---------------------------------------------------------------------------------------------
// Precision types. glslang has no `fixed`; `half` is 32-bit unless 16-bit types are enabled.
// ---------------------------------------------------------------------------------------------
#define fixed half
#define fixed2 half2
#define fixed3 half3
#define fixed4 half4
#define fixed2x2 half2x2
#define fixed3x3 half3x3
#define fixed4x4 half4x4

#define sampler2D_half sampler2D
#define sampler2D_float sampler2D
#define samplerCUBE_half samplerCUBE
#define samplerCUBE_float samplerCUBE
#define sampler3D_half sampler3D
#define sampler3D_float sampler3D
// Unity 2022.3's short spellings (its DXC path makes each a struct of texture and sampler; with
// glslang's DX9-style sampler types and tex* intrinsics they are the plain sampler types).
#define sampler1D_half sampler1D
#define sampler1D_float sampler1D
#define sampler1D_h sampler1D
#define sampler1D_f sampler1D
#define sampler2D_h sampler2D
#define sampler2D_f sampler2D
#define sampler3D_h sampler3D
#define sampler3D_f sampler3D
#define samplerCUBE_h samplerCUBE
#define samplerCUBE_f samplerCUBE

// Shadow coordinates are always full precision.
#define unityShadowCoord float
#define unityShadowCoord2 float2
#define unityShadowCoord3 float3
#define unityShadowCoord4 float4
#define unityShadowCoord4x4 float4x4

// ---------------------------------------------------------------------------------------------
// Blocks, flow-control attributes, misc.
// ---------------------------------------------------------------------------------------------
#ifndef CBUFFER_START
#define CBUFFER_START(name) cbuffer name {
#define CBUFFER_END };
#endif
#define UNITY_BRANCH [branch]
#define UNITY_FLATTEN [flatten]
#define UNITY_UNROLL [unroll]
#define UNITY_UNROLLX(n) [unroll(n)]
#define UNITY_LOOP [loop]

#define UNITY_INITIALIZE_OUTPUT(type, name) name = (type)0;
#define UNITY_PROJ_COORD(a) a
#define UNITY_VPOS_TYPE float4
#define UNITY_POSITION(pos) float4 pos : SV_POSITION
#define UNITY_DECLARE_FRAMEBUFFER_INPUT_FLOAT(idx) sampler2D _UnityFBInput##idx

// ---------------------------------------------------------------------------------------------
// Textures, as on Unity's D3D11 path (UNITY_SEPARATE_TEXTURE_SAMPLER): UNITY_DECLARE_TEX2D(t)
// declares `Texture2D t` and `SamplerState sampler_t`, and code may sample `t.Sample(sampler_t,
// uv)` or share one texture's sampler with others (the _SAMPLER and _NOSAMPLER macros). varc's
// compiler turns every texture into a combined image sampler named after the texture and drops
// the SamplerStates, so a runtime still binds one VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER per
// texture name (docs/SHADER_ABI.md §3). Plain sampler2D/samplerCUBE with tex2D, tex2Dbias,
// tex2Dlod, tex2Dproj, texCUBE, ... (glslang's DX9-compatible intrinsics) work as before.
// ---------------------------------------------------------------------------------------------
#define UNITY_SEPARATE_TEXTURE_SAMPLER
#define UNITY_DECLARE_TEX2D(tex) Texture2D tex; SamplerState sampler##tex
#define UNITY_DECLARE_TEX2D_NOSAMPLER(tex) Texture2D tex
#define UNITY_DECLARE_TEX2D_HALF(tex) Texture2D<half4> tex; SamplerState sampler##tex
#define UNITY_DECLARE_TEX2D_FLOAT(tex) Texture2D<float4> tex; SamplerState sampler##tex
#define UNITY_DECLARE_TEXCUBE(tex) TextureCube tex; SamplerState sampler##tex
#define UNITY_DECLARE_TEXCUBE_NOSAMPLER(tex) TextureCube tex
#define UNITY_DECLARE_TEX3D(tex) Texture3D tex; SamplerState sampler##tex
#define UNITY_SAMPLE_TEX2D(tex, coord) tex.Sample(sampler##tex, coord)
#define UNITY_SAMPLE_TEX2D_SAMPLER(tex, samplertex, coord) tex.Sample(sampler##samplertex, coord)
#define UNITY_SAMPLE_TEX2D_LOD(tex, coord, lod) tex.SampleLevel(sampler##tex, coord, lod)
#define UNITY_SAMPLE_TEXCUBE(tex, coord) tex.Sample(sampler##tex, coord)
#define UNITY_SAMPLE_TEXCUBE_LOD(tex, coord, lod) tex.SampleLevel(sampler##tex, coord, lod)
#define UNITY_SAMPLE_TEXCUBE_SAMPLER(tex, samplertex, coord) tex.Sample(sampler##samplertex, coord)
#define UNITY_SAMPLE_TEX3D(tex, coord) tex.Sample(sampler##tex, coord)

// Depth textures hold raw (non-linear, non-reversed) depth in .r.
#define UNITY_DECLARE_DEPTH_TEXTURE(tex) sampler2D_float tex
#define SAMPLE_DEPTH_TEXTURE(sampler, uv) (tex2D(sampler, uv).r)
#define SAMPLE_DEPTH_TEXTURE_PROJ(sampler, uv) (tex2Dproj(sampler, uv).r)
#define SAMPLE_DEPTH_TEXTURE_LOD(sampler, uv) (tex2Dlod(sampler, uv).r)
#define SAMPLE_RAW_DEPTH_TEXTURE(tex, uv) (tex2D(tex, uv))
#define SAMPLE_RAW_DEPTH_TEXTURE_PROJ(tex, uv) (tex2Dproj(tex, uv))
#define SAMPLE_RAW_DEPTH_TEXTURE_LOD(tex, uv) (tex2Dlod(tex, uv))

// Shadow maps: a plain float depth texture compared in the shader (no comparison sampler), so the
// runtime binds it with an ordinary non-compare sampler. coord = (u, v, depth); 1 = lit.
#define UNITY_DECLARE_SHADOWMAP(tex) sampler2D_float tex
#define UNITY_DECLARE_TEXCUBE_SHADOWMAP(tex) samplerCUBE_float tex
#define UNITY_SAMPLE_SHADOW(tex, coord) ((((coord).z) <= tex2Dlod(tex, float4((coord).xy, 0, 0)).r) ? 1.0 : 0.0)
#define UNITY_SAMPLE_SHADOW_PROJ(tex, coord) UNITY_SAMPLE_SHADOW(tex, ((coord).xyz / (coord).w))
// The screen-space shadow mask: .r is the final shadow attenuation of the main directional light.
#if defined(UNITY_STEREO_INSTANCING_ENABLED) || defined(UNITY_STEREO_MULTIVIEW_ENABLED)
// One slice per eye (unity_StereoEyeIndex, UnityShaderVariables.cginc).
#define UNITY_DECLARE_SCREENSPACE_SHADOWMAP UNITY_DECLARE_TEX2DARRAY
#define UNITY_SAMPLE_SCREEN_SHADOW(tex, uv) UNITY_SAMPLE_TEX2DARRAY(tex, float3((uv).xy / (uv).w, (float)unity_StereoEyeIndex)).r
#else
#define UNITY_DECLARE_SCREENSPACE_SHADOWMAP(tex) sampler2D tex
#define UNITY_SAMPLE_SCREEN_SHADOW(tex, uv) tex2Dproj(tex, UNITY_PROJ_COORD(uv)).r
#endif

// Tessellation attributes under Unity's spellings (`[UNITY_domain("tri")]`), and the pixel
// position input (`UNITY_VPOS_TYPE vpos : VPOS`): the fragment's SV_Position on modern APIs.
#define UNITY_domain domain
#define UNITY_partitioning partitioning
#define UNITY_outputtopology outputtopology
#define UNITY_patchconstantfunc patchconstantfunc
#define UNITY_outputcontrolpoints outputcontrolpoints
#define VPOS SV_Position

// More texture macros, D3D11-style like those above.
#define UNITY_SAMPLE_TEX2D_SAMPLER_LOD(tex, samplertex, coord, lod) tex.SampleLevel(sampler##samplertex, coord, lod)
#define UNITY_SAMPLE_TEXCUBE_SAMPLER_LOD(tex, samplertex, coord, lod) tex.SampleLevel(sampler##samplertex, coord, lod)
// A reflection probe's cube at a given mip level.
#define SampleCubeReflection(env, dir, lod) UNITY_SAMPLE_TEXCUBE_LOD(env, dir, lod)
#define UNITY_SAMPLE_TEX2D_BIAS(tex, coord, bias) tex.SampleBias(sampler##tex, coord, bias)
#define UNITY_SAMPLE_TEXCUBE_BIAS(tex, coord, bias) tex.SampleBias(sampler##tex, coord, bias)
#define UNITY_PASS_TEX2D(tex) tex, sampler##tex
#define UNITY_PASS_TEXCUBE(tex) tex, sampler##tex
#define UNITY_PASS_TEXCUBE_SAMPLER(tex, samplertex) tex, sampler##samplertex
#define UNITY_ARGS_TEX2D(tex) Texture2D tex, SamplerState sampler##tex
#define UNITY_ARGS_TEXCUBE(tex) TextureCube tex, SamplerState sampler##tex
// Screen-space textures (grab passes, camera targets): plain 2D textures in mono rendering.
#if defined(UNITY_STEREO_INSTANCING_ENABLED) || defined(UNITY_STEREO_MULTIVIEW_ENABLED)
#define UNITY_DECLARE_SCREENSPACE_TEXTURE UNITY_DECLARE_TEX2DARRAY
#define UNITY_SAMPLE_SCREENSPACE_TEXTURE(tex, uv) UNITY_SAMPLE_TEX2DARRAY(tex, float3((uv).xy, (float)unity_StereoEyeIndex))
#else
#define UNITY_DECLARE_SCREENSPACE_TEXTURE(tex) sampler2D tex
#define UNITY_SAMPLE_SCREENSPACE_TEXTURE(tex, uv) tex2D(tex, uv)
#endif

// Semi-transparent shadow casters dither against the 3D texture _DitherMaskLOD (SHADER_ABI.md §6).
#define UNITY_USE_DITHER_MASK_FOR_ALPHABLENDED_SHADOWS 1

// ---------------------------------------------------------------------------------------------
// More of Unity's texture API (issue #27, docs/BUILTIN_API.md), in the same D3D11 style: texture
// arrays, cube arrays and 3D textures with and without their own sampler, typed declarations,
// and the argument-passing macros of each.
// ---------------------------------------------------------------------------------------------
#define UNITY_DECLARE_TEX2DARRAY(tex) Texture2DArray tex; SamplerState sampler##tex
#define UNITY_DECLARE_TEX2DARRAY_NOSAMPLER(tex) Texture2DArray tex
#define UNITY_ARGS_TEX2DARRAY(tex) Texture2DArray tex, SamplerState sampler##tex
#define UNITY_ARGS_TEX2DARRAY_NOSAMPLER(tex) Texture2DArray tex
#define UNITY_PASS_TEX2DARRAY(tex) tex, sampler##tex
#define UNITY_PASS_TEX2DARRAY_NOSAMPLER(tex) tex
#define UNITY_SAMPLE_TEX2DARRAY(tex, coord) tex.Sample(sampler##tex, coord)
#define UNITY_SAMPLE_TEX2DARRAY_LOD(tex, coord, lod) tex.SampleLevel(sampler##tex, coord, lod)
#define UNITY_SAMPLE_TEX2DARRAY_SAMPLER(tex, samplertex, coord) tex.Sample(sampler##samplertex, coord)
#define UNITY_SAMPLE_TEX2DARRAY_SAMPLER_LOD(tex, samplertex, coord, lod) tex.SampleLevel(sampler##samplertex, coord, lod)

#define UNITY_DECLARE_TEXCUBEARRAY(tex) TextureCubeArray tex; SamplerState sampler##tex
#define UNITY_DECLARE_TEXCUBEARRAY_NOSAMPLER(tex) TextureCubeArray tex
#define UNITY_ARGS_TEXCUBEARRAY(tex) TextureCubeArray tex, SamplerState sampler##tex
#define UNITY_ARGS_TEXCUBEARRAY_NOSAMPLER(tex) TextureCubeArray tex
#define UNITY_PASS_TEXCUBEARRAY(tex) tex, sampler##tex
#define UNITY_PASS_TEXCUBEARRAY_NOSAMPLER(tex) tex
#define UNITY_SAMPLE_TEXCUBEARRAY(tex, coord) tex.Sample(sampler##tex, coord)
#define UNITY_SAMPLE_TEXCUBEARRAY_LOD(tex, coord, lod) tex.SampleLevel(sampler##tex, coord, lod)
#define UNITY_SAMPLE_TEXCUBEARRAY_SAMPLER(tex, samplertex, coord) tex.Sample(sampler##samplertex, coord)
#define UNITY_SAMPLE_TEXCUBEARRAY_SAMPLER_LOD(tex, samplertex, coord, lod) tex.SampleLevel(sampler##samplertex, coord, lod)

#define UNITY_DECLARE_TEX2D_NOSAMPLER_HALF(tex) Texture2D<half4> tex
#define UNITY_DECLARE_TEX2D_NOSAMPLER_FLOAT(tex) Texture2D<float4> tex
#define UNITY_DECLARE_TEX2D_NOSAMPLER_INT(tex) Texture2D<int4> tex
#define UNITY_DECLARE_TEX2D_NOSAMPLER_UINT(tex) Texture2D<uint4> tex
#define UNITY_DECLARE_TEX3D_HALF(tex) Texture3D<half4> tex; SamplerState sampler##tex
#define UNITY_DECLARE_TEX3D_FLOAT(tex) Texture3D<float4> tex; SamplerState sampler##tex
#define UNITY_DECLARE_TEX3D_NOSAMPLER(tex) Texture3D tex
#define UNITY_SAMPLE_TEX3D_LOD(tex, coord, lod) tex.SampleLevel(sampler##tex, coord, lod)
#define UNITY_SAMPLE_TEX3D_SAMPLER(tex, samplertex, coord) tex.Sample(sampler##samplertex, coord)
#define UNITY_SAMPLE_TEX3D_SAMPLER_LOD(tex, samplertex, coord, lod) tex.SampleLevel(sampler##samplertex, coord, lod)
#define UNITY_ARGS_TEXCUBE_NOSAMPLER(tex) TextureCube tex
#define UNITY_PASS_TEXCUBE_NOSAMPLER(tex) tex

// Texture types of a given precision (half is 32-bit here, like the precision types above).
#define Texture2D_half Texture2D<half4>
#define Texture2D_float Texture2D<float4>
#define Texture2DArray_half Texture2DArray<half4>
#define Texture2DArray_float Texture2DArray<float4>
#define Texture2DMS_half Texture2DMS<half4>
#define Texture2DMS_float Texture2DMS<float4>
#define Texture3D_half Texture3D<half4>
#define Texture3D_float Texture3D<float4>
#define TextureCube_half TextureCube<half4>
#define TextureCube_float TextureCube<float4>
#define TextureCubeArray_half TextureCubeArray<half4>
#define TextureCubeArray_float TextureCubeArray<float4>

// Depth in .r, as SAMPLE_DEPTH_TEXTURE above; cube shadow maps compared like UNITY_SAMPLE_SHADOW
// (coord.xyz the direction, coord.w the receiver's depth; 1 = lit).
#define UNITY_SAMPLE_DEPTH(value) ((value).r)
#define SAMPLE_DEPTH_CUBE_TEXTURE(sampler, uv) (texCUBE(sampler, uv).r)
#define UNITY_SAMPLE_TEXCUBE_SHADOW(tex, coord) ((((coord).w) <= texCUBElod(tex, float4((coord).xyz, 0)).r) ? 1.0 : 0.0)

// ---------------------------------------------------------------------------------------------
// DX9-style sampling glslang lacks. glslang's HLSL front end provides tex1D/tex2D/tex3D/texCUBE
// and their bias, lod, grad and 4-component proj forms itself (docs/BUILTIN_API.md counts those
// rows as native); these add the projective forms it does not have, with Cg's meaning.
// ---------------------------------------------------------------------------------------------
// The 3-component tex2Dproj (xy / z) and 2-component tex1Dproj (x / y). A user overload would
// also capture float4 arguments (glslang prefers truncating to it over its intrinsic), so these
// macros instead widen the coordinate to the intrinsic's float4 form (divisor in w); a float4
// passes through unchanged and compiles exactly as before.
float4 VarcProjCoord2D(float3 t) { return float4(t.xy, 0.0, t.z); }
float4 VarcProjCoord2D(float4 t) { return t; }
float4 VarcProjCoord1D(float2 t) { return float4(t.x, 0.0, 0.0, t.y); }
float4 VarcProjCoord1D(float4 t) { return t; }
#define tex2Dproj(s, t) tex2Dproj(s, VarcProjCoord2D(t))
#define tex1Dproj(s, t) tex1Dproj(s, VarcProjCoord1D(t))
// glslang's own texCUBEproj emits a projective cube sample, which SPIR-V forbids: the
// direction t.xyz / t.w is sampled instead (a positive w does not change the direction).
#define texCUBEproj(s, t) texCUBE(s, (t).xyz / (t).w)
// Shadow-map compares in the style of UNITY_SAMPLE_SHADOW (plain depth texture, no comparison
// sampler; 1 = lit): (u, v, depth) for a float3, projected by w for a float4.
half4 tex2DprojShadow(sampler2D s, in float3 t) {
    return (t.z <= tex2Dlod(s, float4(t.xy, 0, 0)).r) ? 1.0 : 0.0;
}
half4 tex2DprojShadow(sampler2D s, in float4 t) { return tex2DprojShadow(s, t.xyz / t.w); }

// Uniform blocks: Unity's global-block and explicit-binding spellings. Bindings are assigned by
// varc (docs/SHADER_ABI.md §1), so Set and Binding are ignored.
#define GLOBAL_CBUFFER_START(name) CBUFFER_START(name)
#define GLOBAL_CBUFFER_END CBUFFER_END
#define CBUFFER_START_WITH_BINDING(Name, Set, Binding) CBUFFER_START(Name)
#define DECL_WITH_BINDING(Type, Name, Set, Binding) Type Name

// ---------------------------------------------------------------------------------------------
// Compiler and platform facts of Unity's other back ends (issue #27). Unity compiles Vulkan
// programs as D3D11-style HLSL translated by HLSLcc, and varc's glslang front end reads the same
// dialect, so UNITY_COMPILER_HLSLCC holds here. The others describe compilers and platforms that
// varc never targets; they sit under Unity's own conditions so that a program that tests them
// takes the path Unity's Vulkan build takes.
// ---------------------------------------------------------------------------------------------
#define UNITY_COMPILER_HLSLCC 1
#if defined(SHADER_TARGET_SURFACE_ANALYSIS)
#define UNITY_COMPILER_CG 1
#endif
#if defined(SHADER_TARGET_GLSL)
#define UNITY_COMPILER_HLSL2GLSL 1
#endif
#if defined(UNITY_COMPILER_HLSL2GLSL)
#define FACE VFACE
#endif
// Shader model 4.0 features (integer ops, Load, texture arrays) are always there on Vulkan.
#define UNITY_SM40_PLUS_PLATFORM 1
// Clip depth is NOT reversed under varc (0 at the near plane: see UNITY_NEAR_CLIP_VALUE above),
// unlike Unity's own Vulkan build; Unity's file states the reversal for these APIs, and varc's
// Vulkan build keeps it undefined so code testing it computes depth the way varc stores it.
#if defined(SHADER_API_D3D11) || defined(SHADER_API_PSSL) || defined(SHADER_API_XBOXONE) || defined(SHADER_API_METAL)
#define UNITY_REVERSED_Z 1
#endif
#if defined(SHADER_API_GLES) || defined(SHADER_API_GLES3) || defined(SHADER_API_PSP2)
#define UNITY_USE_RGBA_FOR_POINT_SHADOWS 1
#endif
#if defined(SHADER_API_PSP2)
#define UNITY_BUGGY_TEX2DPROJ4 1
#define UNITY_FORCE_LINEAR_READ_FOR_RGBM 1
#endif
#if defined(SHADER_API_D3D9)
#define UNITY_VFACE_AFFECTED_BY_PROJECTION 1
#endif
// Native depth comparisons are available for shadow maps on every API but GLES2.
#if !defined(SHADER_API_GLES) || defined(UNITY_ENABLE_NATIVE_SHADOW_LOOKUPS)
#define SHADOWS_NATIVE 1
#endif
// `fixed` is `half` (see the precision types above) on every API varc targets.
#define UNITY_FIXED_IS_HALF 1
// Gamma-space projects read colours without sRGB conversion (UNITY_COLORSPACE_GAMMA keyword).
#if !defined(UNITY_NO_LINEAR_COLORSPACE) && defined(UNITY_COLORSPACE_GAMMA)
#define UNITY_NO_LINEAR_COLORSPACE 1
#endif
#if defined(UNITY_HDR_ON)
#define HDR_LIGHT_PREPASS_ON 1
#endif
// The "off" spellings of the lightmap keywords of Unity 4, for programs that still test them.
#if !defined(LIGHTMAP_OFF) && !defined(LIGHTMAP_ON)
#define LIGHTMAP_OFF 1
#endif
#if !defined(DIRLIGHTMAP_OFF) && !defined(DIRLIGHTMAP_COMBINED)
#define DIRLIGHTMAP_OFF 1
#endif
#if !defined(DYNAMICLIGHTMAP_OFF) && !defined(DYNAMICLIGHTMAP_ON)
#define DYNAMICLIGHTMAP_OFF 1
#endif
// GLES2 had no unsigned matrices: Unity spells them with int there (never true under varc,
// where glslang knows uintNxM natively).
#if defined(SHADER_API_GLES)
#define uint1x1 int1x1
#define uint1x2 int1x2
#define uint1x3 int1x3
#define uint1x4 int1x4
#define uint2x1 int2x1
#define uint2x2 int2x2
#define uint2x3 int2x3
#define uint2x4 int2x4
#define uint3x1 int3x1
#define uint3x2 int3x2
#define uint3x3 int3x3
#define uint3x4 int3x4
#define uint4x1 int4x1
#define uint4x2 int4x2
#define uint4x3 int4x3
#define uint4x4 int4x4
#endif
// Unity's DXC path emulates sampler2D & co. as structs unless DXC_SAMPLER_COMPATIBILITY is set;
// varc does not compile with DXC (glslang's sampler types are native).
#if defined(UNITY_COMPILER_DXC) && !defined(DXC_SAMPLER_COMPATIBILITY)
#define DXC_SAMPLER_COMPATIBILITY 1
#endif
// The Cg compiler of surface-shader analysis lacks the gradient forms and texture arrays.
// (tex2D & co. with derivative arguments are the gradient forms there.)
#if defined(UNITY_COMPILER_CG)
#define tex2Dgrad tex2D
#define tex3Dgrad tex3D
#define texCUBEgrad texCUBE
#endif
#if defined(SHADER_TARGET_SURFACE_ANALYSIS)
#define sampler2DArray sampler3D
#define tex2DArray tex3D
#define tex2DArraylod tex3Dlod
#endif

// ---------------------------------------------------------------------------------------------
// DX9-era spellings with their Vulkan meaning.
// ---------------------------------------------------------------------------------------------
// Rectangle textures: SPIR-V's SampledRect is not allowed on Vulkan, so (as on Unity's D3D11
// path) a samplerRECT is a 2D texture sampled with normalised coordinates.
#define samplerRECT sampler2D
#define texRECT tex2D
#define texRECTlod tex2Dlod
#define texRECTbias tex2Dbias
#define texRECTproj tex2Dproj
// Storage qualifiers of sampler and constant declarations (PSSL needed none).
#if defined(SHADER_API_PSSL)
#define SAMPLER_UNIFORM
#define SHADER_UNIFORM
#else
#define SAMPLER_UNIFORM uniform
#define SHADER_UNIFORM uniform
#endif
// The fog coordinate and pixel position semantics of Unity 4 programs.
#define FOGC FOG
#define WPOS VPOS
// The channel that holds alpha, and a single-channel read (x = sampler, y = coordinate).
#define UNITY_ALPHA_CHANNEL a
#define UNITY_SAMPLE_1CHANNEL(x, y) tex2D(x, y).UNITY_ALPHA_CHANNEL
// An optimisation hint of Unity's D3D compiler: nothing for glslang.
#define UNITY_FASTOPT
// Advanced blend equations (KHR_blend_equation_advanced) are a GLES 3 request: nothing here.
#define UNITY_REQUIRE_ADVANCED_BLEND(mode)
#define UNITY_PASS_TEXCUBE_SAMPLER_LOD(tex, samplertex, lod) tex, sampler##samplertex, lod

// ---------------------------------------------------------------------------------------------
// Multisampled textures. varc's runtime renders one sample per pixel (GetRenderTargetSampleCount()
// is 1), so an _MS texture is its single-sample form and a sample index reads sample 0.
// ---------------------------------------------------------------------------------------------
#define UNITY_DECLARE_DEPTH_TEXTURE_MS(tex) Texture2D<float> tex
#define UNITY_DECLARE_TEX2DARRAY_MS(tex) Texture2DArray tex; SamplerState sampler##tex
#define UNITY_DECLARE_TEX2DARRAY_MS_NOSAMPLER(tex) Texture2DArray tex

// ---------------------------------------------------------------------------------------------
// Framebuffer fetch. Vulkan's input attachments need a subpass that varc's runtime does not set
// up, so (as Unity does where fetch is unavailable) each input is a texture of the same target
// read at the fragment's pixel: v2fname is the SV_Position (pixel centre) of the fragment.
// Every type reads as float4; INT/UINT callers convert. _MS forms ignore the sample index.
// ---------------------------------------------------------------------------------------------
#define UNITY_DECLARE_FRAMEBUFFER_INPUT_HALF(idx) sampler2D _UnityFBInput##idx
#define UNITY_DECLARE_FRAMEBUFFER_INPUT_INT(idx) sampler2D _UnityFBInput##idx
#define UNITY_DECLARE_FRAMEBUFFER_INPUT_UINT(idx) sampler2D _UnityFBInput##idx
#define UNITY_DECLARE_FRAMEBUFFER_INPUT_FLOAT_MS(idx) sampler2D _UnityFBInput##idx
#define UNITY_DECLARE_FRAMEBUFFER_INPUT_HALF_MS(idx) sampler2D _UnityFBInput##idx
#define UNITY_DECLARE_FRAMEBUFFER_INPUT_INT_MS(idx) sampler2D _UnityFBInput##idx
#define UNITY_DECLARE_FRAMEBUFFER_INPUT_UINT_MS(idx) sampler2D _UnityFBInput##idx
#define UNITY_READ_FRAMEBUFFER_INPUT(idx, v2fname) tex2Dlod(_UnityFBInput##idx, float4((v2fname).xy * (_ScreenParams.zw - 1.0), 0, 0))
#define UNITY_READ_FRAMEBUFFER_INPUT_MS(idx, sampleIdx, v2fname) UNITY_READ_FRAMEBUFFER_INPUT(idx, v2fname)
#define UNITY_DXC_SUBPASS_INPUT_TYPE_INDEX(type, idx) sampler2D _UnityFBInput##idx
#define UNITY_DXC_SUBPASS_INPUT_TYPE_INDEX_MS(type, idx) sampler2D _UnityFBInput##idx
#if defined(SHADER_API_METAL) && defined(UNITY_NEEDS_RENDERPASS_FBFETCH_FALLBACK)
#define UNITY_RENDERPASS_DECLARE_FALLBACK(T, idx) Texture2D<T> _UnityFBInput##idx
#define UNITY_RENDERPASS_DECLARE_FALLBACK_MS(T, idx) Texture2D<T> _UnityFBInput##idx
#endif

// ---------------------------------------------------------------------------------------------
// Display-orientation pre-transform (Vulkan on Android rotates the swapchain in the shader).
// varc presents nothing: the orientation is always 0 (no rotation), and applying it is the
// identity.
// ---------------------------------------------------------------------------------------------
#define UNITY_DISPLAY_ORIENTATION_PRETRANSFORM_0 0
#define UNITY_DISPLAY_ORIENTATION_PRETRANSFORM_90 1
#define UNITY_DISPLAY_ORIENTATION_PRETRANSFORM_180 2
#define UNITY_DISPLAY_ORIENTATION_PRETRANSFORM_270 3
static const int UnityDisplayOrientationPreTransform = UNITY_DISPLAY_ORIENTATION_PRETRANSFORM_0;
#define UNITY_DISPLAY_ORIENTATION_PRETRANSFORM UnityDisplayOrientationPreTransform


#endif // HLSL_SUPPORT_INCLUDED
