// SPDX-License-Identifier: Apache-2.0
// varc built-in: SRP core ShaderLibrary/Common.hlsl. The platform layer scriptable-pipeline
// shaders include first: `real` precision types, CBUFFER_START/END, separate texture/sampler
// macros (TEXTURE2D, SAMPLER, SAMPLE_TEXTURE2D...), constants and small math helpers, for
// glslang's HLSL front end targeting Vulkan. It declares no built-in variables: an SRP shader
// declares its own (e.g. unity_MatrixVP, unity_ObjectToWorld) and the runtime fills them by name
// (docs/SHADER_ABI.md). Written for varc; not derived from Unity's file.
#ifndef UNITY_COMMON_INCLUDED
#define UNITY_COMMON_INCLUDED

#ifndef SHADER_TARGET
#define SHADER_TARGET 25
#endif

// ---------------------------------------------------------------------------------------------
// Platform (Vulkan): see HLSLSupport.cginc for the same facts in the built-in library.
// ---------------------------------------------------------------------------------------------
#define UNITY_UV_STARTS_AT_TOP 1
#define UNITY_NEAR_CLIP_VALUE (0.0)
#define UNITY_RAW_FAR_CLIP_VALUE (1.0)
#define UNITY_NO_DXT5nm 1
#define SHADER_API_VULKAN_VARC 1

#ifndef CBUFFER_START
#define CBUFFER_START(name) cbuffer name {
#define CBUFFER_END };
#endif

#define UNITY_BRANCH [branch]
#define UNITY_FLATTEN [flatten]
#define UNITY_UNROLL [unroll]
#define UNITY_UNROLLX(n) [unroll(n)]
#define UNITY_LOOP [loop]

// `real` is full precision (half is 32-bit without --hlsl-enable-16bit-types).
#define real float
#define real2 float2
#define real3 float3
#define real4 float4
#define real2x2 float2x2
#define real3x3 float3x3
#define real4x4 float4x4
#define REAL_MIN FLT_MIN
#define REAL_MAX FLT_MAX
#define REAL_EPS FLT_EPS

// ---------------------------------------------------------------------------------------------
// Textures: separate Texture*/SamplerState objects (VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE +
// VK_DESCRIPTOR_TYPE_SAMPLER, each found by name in the reflection).
// ---------------------------------------------------------------------------------------------
#define TEXTURE2D(textureName) Texture2D textureName
#define TEXTURE2D_ARRAY(textureName) Texture2DArray textureName
#define TEXTURECUBE(textureName) TextureCube textureName
#define TEXTURE3D(textureName) Texture3D textureName
#define TEXTURE2D_FLOAT(textureName) Texture2D_float textureName
#define TEXTURE2D_SHADOW(textureName) Texture2D textureName
#define SAMPLER(samplerName) SamplerState samplerName
#define SAMPLER_CMP(samplerName) SamplerComparisonState samplerName
#define TEXTURE2D_ARGS(textureName, samplerName) Texture2D textureName, SamplerState samplerName
#define TEXTURE2D_PARAM(textureName, samplerName) textureName, samplerName
#define TEXTURECUBE_ARGS(textureName, samplerName) TextureCube textureName, SamplerState samplerName
#define TEXTURECUBE_PARAM(textureName, samplerName) textureName, samplerName
#define SAMPLE_TEXTURE2D(textureName, samplerName, coord2) textureName.Sample(samplerName, coord2)
#define SAMPLE_TEXTURE2D_LOD(textureName, samplerName, coord2, lod) textureName.SampleLevel(samplerName, coord2, lod)
#define SAMPLE_TEXTURE2D_BIAS(textureName, samplerName, coord2, bias) textureName.SampleBias(samplerName, coord2, bias)
#define SAMPLE_TEXTURE2D_ARRAY(textureName, samplerName, coord2, index) textureName.Sample(samplerName, float3(coord2, index))
#define SAMPLE_TEXTURECUBE(textureName, samplerName, coord3) textureName.Sample(samplerName, coord3)
#define SAMPLE_TEXTURECUBE_LOD(textureName, samplerName, coord3, lod) textureName.SampleLevel(samplerName, coord3, lod)
#define SAMPLE_TEXTURE3D(textureName, samplerName, coord3) textureName.Sample(samplerName, coord3)
#define SAMPLE_TEXTURE2D_SHADOW(textureName, samplerName, coord3) textureName.SampleCmpLevelZero(samplerName, (coord3).xy, (coord3).z)
#define LOAD_TEXTURE2D(textureName, unCoord2) textureName.Load(int3(unCoord2, 0))
#define LOAD_TEXTURE2D_LOD(textureName, unCoord2, lod) textureName.Load(int3(unCoord2, lod))
#define SAMPLE_DEPTH_TEXTURE(textureName, samplerName, coord2) SAMPLE_TEXTURE2D(textureName, samplerName, coord2).r

// ---------------------------------------------------------------------------------------------
// Constants and helpers.
// ---------------------------------------------------------------------------------------------
#define PI 3.14159265358979323846
#define TWO_PI 6.28318530717958647693
#define FOUR_PI 12.5663706143591729538
#define INV_PI 0.31830988618379067154
#define INV_TWO_PI 0.15915494309189533577
#define INV_FOUR_PI 0.07957747154594766788
#define HALF_PI 1.57079632679489661923
#define INV_HALF_PI 0.63661977236758134308
#define FLT_EPS 5.960464478e-8
#define FLT_MIN 1.175494351e-38
#define FLT_MAX 3.402823466e+38
#define HALF_MIN 6.103515625e-5
#define HALF_MAX 65504.0

float Sq(float x) { return x * x; }
float Max3(float a, float b, float c) { return max(max(a, b), c); }
float Min3(float a, float b, float c) { return min(min(a, b), c); }
// pow() for a base that may be negative or zero: |base|^power.
float PositivePow(float base, float power) { return pow(max(abs(base), float(FLT_EPS)), power); }
float3 PositivePow(float3 base, float3 power) { return pow(max(abs(base), float3(FLT_EPS, FLT_EPS, FLT_EPS)), power); }
// x / |x| with |x|^2 clamped to FLT_MIN.
float3 SafeNormalize(float3 inVec) { return inVec * rsqrt(max(FLT_MIN, dot(inVec, inVec))); }
// Raw depth z in [0,1] -> eye depth / far and eye depth, given _ZBufferParams-style parameters.
float Linear01Depth(float depth, float4 zBufferParam) { return 1.0 / (zBufferParam.x * depth + zBufferParam.y); }
float LinearEyeDepth(float depth, float4 zBufferParam) { return 1.0 / (zBufferParam.z * depth + zBufferParam.w); }

#endif // UNITY_COMMON_INCLUDED
