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
#define UNITY_DECLARE_SCREENSPACE_SHADOWMAP(tex) sampler2D tex
#define UNITY_SAMPLE_SCREEN_SHADOW(tex, uv) tex2Dproj(tex, UNITY_PROJ_COORD(uv)).r

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
#define UNITY_DECLARE_SCREENSPACE_TEXTURE(tex) sampler2D tex
#define UNITY_SAMPLE_SCREENSPACE_TEXTURE(tex, uv) tex2D(tex, uv)

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

#endif // HLSL_SUPPORT_INCLUDED
