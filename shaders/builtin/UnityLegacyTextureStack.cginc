// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityLegacyTextureStack.cginc. Texture stacks (Unity 2020.3+): the macros a
// shader samples its stackable textures through, so that one source builds with streaming virtual
// texturing (UNITY_VIRTUAL_TEXTURING, through GraniteShaderLib3.cginc) and without it (plain
// sampling). Written for varc from the documented behaviour.
//
// varc has no virtual-texturing runtime on Vulkan (no tile cache, no translation table, no
// feedback read-back), so both branches sample the named texture directly: without
// UNITY_VIRTUAL_TEXTURING exactly as Unity does, with it as a fallback that keeps the same macro
// arities and StackInfo members and reports no feedback (a zero resolve output).
#ifndef TEXTURESTACK_include
#define TEXTURESTACK_include

// Granite's configuration for stacks, set before it is included.
#define GRA_HLSL_5 1
#define GRA_ROW_MAJOR 1
#define GRA_TEXTURE_ARRAY_SUPPORT 1
#define GRA_PACK_RESOLVE_OUTPUT 0
#if SHADER_API_PSSL
#define GRA_NO_UNORM 1
#endif
#include "GraniteShaderLib3.cginc"

#ifndef RESOLVE_SCALE_OVERRIDE
#define RESOLVE_SCALE_OVERRIDE float2(1, 1)
#endif

#if UNITY_VIRTUAL_TEXTURING
#define VIRTUAL_TEXTURES_ACTIVE 1
#else
#define VIRTUAL_TEXTURES_ACTIVE 0
#endif

// The lookups a stack uses (TEXTURESTACK_CLAMP: the clamped variants).
#if defined(TEXTURESTACK_CLAMP)
#define GR_LOOKUP Granite_Lookup_Clamp_Linear
#define GR_LOOKUP_LOD Granite_Lookup_Clamp
#else
#define GR_LOOKUP Granite_Lookup_Anisotropic
#define GR_LOOKUP_LOD Granite_Lookup
#endif

// What PrepareStack gives SampleStack: the coordinates (and level) to sample at and, with
// virtual texturing, the lookups and the feedback of the pixel.
struct StackInfo {
#if VIRTUAL_TEXTURES_ACTIVE
    GraniteLookupData lookupData;
    GraniteLODLookupData lookupDataLod;
    float4 resolveOutput;
#else
    float2 uv;
    float lod;
#endif
};

// The tangent-space normal of a normal-map texel scaled by |scale| (UnpackNormalWithScale of
// UnityCG.cginc, restated so that this file stands alone): rgb * 2 - 1 with UNITY_NO_DXT5nm,
// else x from alpha (or red) and y from green, z rebuilt.
float3 VarcStack_UnpackNormal(float4 packed, float scale) {
#if defined(UNITY_NO_DXT5nm)
    float3 n = packed.xyz * 2 - 1;
    n.xy *= scale;
    return n;
#else
    packed.x *= packed.w;
    float3 n;
    n.xy = (packed.xy * 2 - 1) * scale;
    n.z = sqrt(1 - saturate(dot(n.xy, n.xy)));
    return n;
#endif
}

#define jj(a, b) a##b
#define jj2(a, b) jj(a, b)

#if VIRTUAL_TEXTURES_ACTIVE

// Unity binds the tile sets of all stacks here; the fallback never reads it.
StructuredBuffer<GraniteTilesetConstantBuffer> _VTTilesetBuffer;
SamplerState _vt_cacheSampler_trilinear_clamp_aniso4;

// A stack's declarations: the fallback needs none (it samples each layer's own texture).
#define DECLARE_STACK_CB(stackName)
#define DECLARE_STACK_BASE(stackName)
#define DECLARE_STACK_RESOLVE(stackName)
#define DECLARE_STACK_LAYER(stackName, layerSamplerName, layerIndex)
#define DECLARE_STACK(stackName, layer0SamplerName) DECLARE_STACK_BASE(stackName)
#define DECLARE_STACK2(stackName, layer0SamplerName, layer1SamplerName) DECLARE_STACK_BASE(stackName)
#define DECLARE_STACK3(stackName, layer0SamplerName, layer1SamplerName, layer2SamplerName) \
    DECLARE_STACK_BASE(stackName)
#define DECLARE_STACK4(stackName, layer0SamplerName, layer1SamplerName, layer2SamplerName, \
                       layer3SamplerName)                                                  \
    DECLARE_STACK_BASE(stackName)

// The lookups of |uv| with explicit gradients (or a level): the coordinates pass through
// untranslated and the feedback is zero (no tile is ever requested).
StackInfo VarcStack_MakeInfo(float2 uv, float2 dx, float2 dy, float lod) {
    StackInfo info;
    info.lookupData.textureCoordinates = uv;
    info.lookupData.translationTableData = float4(0, 0, 0, 0);
    info.lookupData.dX = dx;
    info.lookupData.dY = dy;
    info.lookupDataLod.textureCoordinates = uv;
    info.lookupDataLod.translationTableData = float4(0, 0, 0, 0);
    info.lookupDataLod.cacheLevel = lod;
    info.resolveOutput = float4(0, 0, 0, 0);
    return info;
}

// Feedback packed for the resolve target: the fallback's feedback is already zero.
float4 GetPackedVTFeedback(float4 feedback) {
    return Granite_PackTileId(feedback);
}

#define PrepareStack(uv, stackName) VarcStack_MakeInfo(uv, ddx(uv), ddy(uv), 0)
#define PrepareStackLod(uv, stackName, mip) VarcStack_MakeInfo(uv, float2(0, 0), float2(0, 0), mip)
#define SampleStack(info, textureName) \
    tex2Dgrad(textureName, (info).lookupData.textureCoordinates, (info).lookupData.dX, (info).lookupData.dY)
#define SampleStackLod(info, textureName) \
    tex2Dlod(textureName, float4((info).lookupDataLod.textureCoordinates, 0, (info).lookupDataLod.cacheLevel))
#define SampleStackNormal(info, textureName, scale) VarcStack_UnpackNormal(SampleStack(info, textureName), scale)
#define SampleStackLodNormal(info, textureName, scale) \
    VarcStack_UnpackNormal(SampleStackLod(info, textureName), scale)
#define GetResolveOutput(info) ((info).resolveOutput)
#define PackResolveOutput(output) GetPackedVTFeedback(output)
#define ResolveStack(uv, stackName) float4(0, 0, 0, 0)

#else  // !VIRTUAL_TEXTURES_ACTIVE: plain sampling, as in Unity.

#define DECLARE_STACK_CB(stackName)
#define DECLARE_STACK(stackName, layer0)
#define DECLARE_STACK2(stackName, layer0, layer1)
#define DECLARE_STACK3(stackName, layer0, layer1, layer2)
#define DECLARE_STACK4(stackName, layer0, layer1, layer2, layer3)

StackInfo MakeStackInfo(float2 uv) {
    StackInfo info;
    info.uv = uv;
    info.lod = 0;
    return info;
}

StackInfo MakeStackInfoLod(float2 uv, float lod) {
    StackInfo info;
    info.uv = uv;
    info.lod = lod;
    return info;
}

#define PrepareStack(uv, stackName) MakeStackInfo(uv)
#define PrepareStackLod(uv, stackName, mip) MakeStackInfoLod(uv, mip)
#define SampleStack(info, texture) tex2D(texture, (info).uv)
#define SampleStackLod(info, texture) tex2Dlod(texture, float4((info).uv, 0, (info).lod))
#define SampleStackNormal(info, texture, scale) VarcStack_UnpackNormal(SampleStack(info, texture), scale)
#define SampleStackLodNormal(info, texture, scale) VarcStack_UnpackNormal(SampleStackLod(info, texture), scale)
#define GetResolveOutput(info) float4(0, 0, 0, 0)
#define PackResolveOutput(output) output
#define ResolveStack(uv, stackName) float4(0, 0, 0, 0)

#endif  // VIRTUAL_TEXTURES_ACTIVE

#endif  // TEXTURESTACK_include
