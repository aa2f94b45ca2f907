// SPDX-License-Identifier: Apache-2.0
// varc built-in: GraniteShaderLib3.cginc. The shader side of Granite streaming virtual texturing
// (Unity 2020.3+, used by UnityLegacyTextureStack.cginc): configuration macros, the constant
// buffer and lookup types, and the lookup / sample / resolve entry points. Written for varc from
// the API's signatures and the documented behaviour.
//
// Fallback: varc has no virtual-texturing runtime on Vulkan (no tile streaming, no translation
// table, no feedback read-back). Every lookup therefore succeeds (returns 1) with the texture's
// own coordinates after the lookup's address mode (repeat, clamp or UDIM) and an identity page
// translation, every sample reads the cache texture at those coordinates (the application binds
// the whole texture as the cache), and every resolve output is zero: no tile is ever requested.
// The constant-buffer layout below is varc's own; only the documented accessors read it.
#ifndef GRANITE_SHADER_LIB3_INCLUDED
#define GRANITE_SHADER_LIB3_INCLUDED

// Target selection: glslang's HLSL front end is Shader Model 5.
#ifndef GRA_HLSL_3
#define GRA_HLSL_3 0
#endif
#ifndef GRA_HLSL_4
#define GRA_HLSL_4 0
#endif
#ifndef GRA_HLSL_5
#define GRA_HLSL_5 1
#endif
#ifndef GRA_GLSL_120
#define GRA_GLSL_120 0
#endif
#ifndef GRA_GLSL_130
#define GRA_GLSL_130 0
#endif
#ifndef GRA_GLSL_330
#define GRA_GLSL_330 0
#endif
#ifndef GRA_VERTEX_SHADER
#define GRA_VERTEX_SHADER 0
#endif
#ifndef GRA_PIXEL_SHADER
#define GRA_PIXEL_SHADER 0
#endif
#define GRA_HLSL_FAMILY ((GRA_HLSL_3 == 1) || (GRA_HLSL_4 == 1) || (GRA_HLSL_5 == 1))
#define GRA_GLSL_FAMILY ((GRA_GLSL_120 == 1) || (GRA_GLSL_130 == 1) || (GRA_GLSL_330 == 1))

// Features and debugging switches (0 = off), each overridable before the include.
#ifndef GRA_ROW_MAJOR
#define GRA_ROW_MAJOR 1
#endif
#ifndef GRA_64BIT_RESOLVER
#define GRA_64BIT_RESOLVER 0
#endif
#ifndef GRA_BGRA
#define GRA_BGRA 0
#endif
#ifndef GRA_DEBUG
#define GRA_DEBUG 0
#endif
#ifndef GRA_DEBUG_TILES
#define GRA_DEBUG_TILES 0
#endif
#ifndef GRA_DISABLE_TEX_LOAD
#define GRA_DISABLE_TEX_LOAD 0
#endif
#ifndef GRA_FORCE_SM3
#define GRA_FORCE_SM3 0
#endif
#ifndef GRA_HQ_CUBEMAPPING
#define GRA_HQ_CUBEMAPPING 0
#endif
#ifndef GRA_PACK_RESOLVE_OUTPUT
#define GRA_PACK_RESOLVE_OUTPUT 1
#endif
// The resolve (feedback) target is this many times smaller than the screen on each axis.
#ifndef GRA_RWTEXTURE2D_SCALE
#define GRA_RWTEXTURE2D_SCALE 16
#endif
#ifndef GRA_TEXTURE_ARRAY_SUPPORT
#if (GRA_HLSL_5 == 1) || (GRA_HLSL_4 == 1) || (GRA_GLSL_330 == 1)
#define GRA_TEXTURE_ARRAY_SUPPORT 1
#else
#define GRA_TEXTURE_ARRAY_SUPPORT 0
#endif
#endif
#if (GRA_HLSL_5 == 1) || (GRA_HLSL_4 == 1) || (GRA_GLSL_130 == 1) || (GRA_GLSL_330 == 1)
#define GRA_LOAD_INSTR 1
#else
#define GRA_LOAD_INSTR 0
#endif
#if !(GRA_DISABLE_TEX_LOAD != 1)
#undef GRA_LOAD_INSTR
#define GRA_LOAD_INSTR 0
#endif
#if defined(GRA_NO_UNORM)
#define GRA_UNORM
#else
#define GRA_UNORM unorm
#endif

// Language vocabulary: HLSL names, or their GLSL spellings for the GLSL family.
#if GRA_HLSL_FAMILY
#define gra_Float2 float2
#define gra_Float3 float3
#define gra_Float4 float4
#define gra_Int3 int3
#define gra_Float4x4 float4x4
#define gra_Unroll [unroll]
#define gra_Branch [branch]
#elif !((GRA_VERTEX_SHADER == 0) && (GRA_PIXEL_SHADER == 0))
#define gra_Float2 vec2
#define gra_Float3 vec3
#define gra_Float4 vec4
#define gra_Int3 ivec3
#define gra_Float4x4 mat4
#define gra_Unroll
#define gra_Branch
#define frac fract
#define lerp mix
#define fmod mod
#if (GRA_VERTEX_SHADER == 1)
#define ddx 0.0 *
#define ddy 0.0 *
#elif (GRA_PIXEL_SHADER == 1)
#define ddx dFdx
#define ddy dFdy
#endif
#endif

// Sizes of the constant buffers, in rows.
#define _grTilesetCBSize 2
#define _grStreamingTextureCBSize 2
#define _grStreamingTextureCubeCBSize 6

// A tile set: data[0] its parameters, data[1] the per-layer cache parameters.
struct GraniteTilesetConstantBuffer {
    gra_Float4x4 data[_grTilesetCBSize];
};
// A streaming texture: data[0] its transform into the tile set (scale xy, offset zw), data[1]
// its size in texels (xy) and id (z).
struct GraniteStreamingTextureConstantBuffer {
    gra_Float4 data[_grStreamingTextureCBSize];
};
// A cube map: one streaming texture per face (+X, -X, +Y, -Y, +Z, -Z).
struct GraniteStreamingTextureCubeConstantBuffer {
    GraniteStreamingTextureConstantBuffer data[_grStreamingTextureCubeCBSize];
};
struct GraniteConstantBuffers {
    GraniteTilesetConstantBuffer tilesetBuffer;
    GraniteStreamingTextureConstantBuffer streamingTextureBuffer;
};
struct GraniteCubeConstantBuffers {
    GraniteTilesetConstantBuffer tilesetBuffer;
    GraniteStreamingTextureCubeConstantBuffer streamingTextureCubeBuffer;
};

// The accessors of the buffers above, written against the parameter names the API uses
// (grCB, tsCB, grSTCB, transforms).
#define gra_TilesetBuffer grCB.tilesetBuffer
#define gra_StreamingTextureCB grCB.streamingTextureBuffer
#define gra_StreamingTextureCubeCB grCB.streamingTextureCubeBuffer
#define gra_TilesetBufferInternal tsCB.data[0]
#define gra_TilesetCacheBuffer tsCB.data[1]
#define gra_StreamingTextureTransform grSTCB.data[0]
#define gra_StreamingTextureInfo grSTCB.data[1]
#define gra_Transform gra_StreamingTextureTransform
#define gra_CubeTransform transforms.data
#define gra_NumLevels gra_TilesetBufferInternal[3][3]
#if GRA_ROW_MAJOR == 1
#define gra_AssetWidthRcp gra_TilesetBufferInternal[0][0]
#define gra_AssetHeightRcp gra_TilesetBufferInternal[0][1]
#define gra_TranslationTableBias gra_TilesetBufferInternal[0][2]
#define gra_MaxAnisotropyLog2 gra_TilesetBufferInternal[0][3]
#define gra_CalcMiplevelDeltaScale gra_TilesetBufferInternal[1].xy
#define gra_CalcMiplevelDeltaScaleX gra_TilesetBufferInternal[1][0]
#define gra_CalcMiplevelDeltaScaleY gra_TilesetBufferInternal[1][1]
#define gra_LodBiasPow2 gra_TilesetBufferInternal[1][2]
#define gra_TileContentInTiles gra_TilesetBufferInternal[2].xy
#define gra_Level0NumTilesX gra_TilesetBufferInternal[2][2]
#define gra_NumTilesYScale gra_TilesetBufferInternal[2][3]
#define gra_TextureMagic gra_TilesetBufferInternal[3][0]
#define gra_TextureId gra_TilesetBufferInternal[3][1]
#define gra_RcpCacheInTiles(l) gra_TilesetCacheBuffer[l].xy
#define gra_BorderPixelsRcpCache(l) gra_TilesetCacheBuffer[l].zw
#else
#define gra_AssetWidthRcp gra_TilesetBufferInternal[0][0]
#define gra_AssetHeightRcp gra_TilesetBufferInternal[1][0]
#define gra_TranslationTableBias gra_TilesetBufferInternal[2][0]
#define gra_MaxAnisotropyLog2 gra_TilesetBufferInternal[3][0]
#define gra_CalcMiplevelDeltaScale float2(gra_TilesetBufferInternal[0][1], gra_TilesetBufferInternal[1][1])
#define gra_CalcMiplevelDeltaScaleX gra_TilesetBufferInternal[0][1]
#define gra_CalcMiplevelDeltaScaleY gra_TilesetBufferInternal[1][1]
#define gra_LodBiasPow2 gra_TilesetBufferInternal[2][1]
#define gra_TileContentInTiles float2(gra_TilesetBufferInternal[0][2], gra_TilesetBufferInternal[1][2])
#define gra_Level0NumTilesX gra_TilesetBufferInternal[2][2]
#define gra_NumTilesYScale gra_TilesetBufferInternal[3][2]
#define gra_TextureMagic gra_TilesetBufferInternal[0][3]
#define gra_TextureId gra_TilesetBufferInternal[1][3]
#define gra_RcpCacheInTiles(l) float2(gra_TilesetCacheBuffer[0][l], gra_TilesetCacheBuffer[1][l])
#define gra_BorderPixelsRcpCache(l) float2(gra_TilesetCacheBuffer[2][l], gra_TilesetCacheBuffer[3][l])
#endif

// What a lookup hands to a sample: the coordinates and the page translation (scale xy,
// offset zw), with the gradients (anisotropic / linear lookups) or the level (LOD lookups).
struct GraniteLookupData {
    gra_Float4 translationTableData;
    gra_Float2 textureCoordinates;
    gra_Float2 dX;
    gra_Float2 dY;
};
struct GraniteLODLookupData {
    gra_Float4 translationTableData;
    gra_Float2 textureCoordinates;
    float cacheLevel;
};

// The translation table and the cache textures: a texture and its sampler on Shader Model 4/5,
// a combined sampler elsewhere.
#if (GRA_HLSL_5 == 1) || (GRA_HLSL_4 == 1)
struct GraniteTranslationTexture {
    SamplerState Sampler;
    Texture2D Texture;
};
struct GraniteCacheTexture {
    SamplerState Sampler;
#if GRA_TEXTURE_ARRAY_SUPPORT
    Texture2DArray TextureArray;
#else
    Texture2D Texture;
#endif
};
#elif (GRA_HLSL_3 == 1) || (GRA_GLSL_120 == 1) || (GRA_GLSL_130 == 1) || (GRA_GLSL_330 == 1)
#define GraniteTranslationTexture sampler2D
#if GRA_TEXTURE_ARRAY_SUPPORT
#define GraniteCacheTexture sampler2DArray
#else
#define GraniteCacheTexture sampler2D
#endif
#endif

#include "VarcGraniteCore.cginc"
#include "VarcGraniteSoftware.cginc"
#include "VarcGraniteLookups.cginc"
#include "VarcGraniteResolve.cginc"

#endif  // GRANITE_SHADER_LIB3_INCLUDED
