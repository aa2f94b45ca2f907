// SPDX-License-Identifier: Apache-2.0
// varc built-in, part of GraniteShaderLib3.cginc: the address modes, mip-level and cube-face
// arithmetic, tile ids, cache sampling and buffer setters the lookups build on (see the fallback
// note at the top of GraniteShaderLib3.cginc). Written for varc.
#include "GraniteShaderLib3.cginc"
#ifndef VARC_GRANITE_CORE_INCLUDED
#define VARC_GRANITE_CORE_INCLUDED

float GranitePrivate_Saturate(in float value) {
    return saturate(value);
}

#if (GRA_HLSL_5 == 1) || (GRA_HLSL_4 == 1) || (GRA_GLSL_330 == 1)
uint GranitePrivate_FloatAsUint(float value) {
    return asuint(value);
}
#endif

// 2^exponent.
#if (GRA_FORCE_SM3 == 0) && ((GRA_HLSL_5 == 1) || (GRA_HLSL_4 == 1) || (GRA_GLSL_330 == 1))
float GranitePrivate_Pow2(uint exponent) {
    return (float)(1u << exponent);
}
#else
float GranitePrivate_Pow2(int exponent) {
    return exp2((float)exponent);
}
#endif

// The streaming texture's coordinates in its tile set: uv * scale + offset.
gra_Float2 Granite_Transform(in GraniteStreamingTextureConstantBuffer grSTCB, in gra_Float2 textureCoord) {
    return textureCoord * gra_Transform.xy + gra_Transform.zw;
}

// Address modes: repeat, clamp to [0, 1], mirror (period 2), UDIM (tiles laid out beyond
// [0, 1], kept as they are).
gra_Float2 GranitePrivate_RepeatUV(in gra_Float2 uv, in GraniteStreamingTextureConstantBuffer grSTCB) {
    return frac(uv);
}
gra_Float2 GranitePrivate_ClampUV(in gra_Float2 uv, in GraniteStreamingTextureConstantBuffer grSTCB) {
    return saturate(uv);
}
gra_Float2 GranitePrivate_MirrorUV(in gra_Float2 uv, in GraniteStreamingTextureConstantBuffer grSTCB) {
    return 1 - abs(frac(uv * 0.5) * 2 - 1);
}
gra_Float2 GranitePrivate_UdimUV(in gra_Float2 uv, in GraniteStreamingTextureConstantBuffer grSTCB) {
    return uv;
}

// The streaming texture's size in texels.
gra_Float2 Granite_GetTextureDimensions(in GraniteStreamingTextureConstantBuffer grSTCB) {
    return gra_StreamingTextureInfo.xy;
}

// Mip level of the texel-space footprint of the gradients: linear filtering takes the longer
// axis, log2(max(|dx|, |dy|)); anisotropic filtering the longer axis over the anisotropy
// N = min(longer / shorter, 2^maxAnisotropyLog2), log2(longer / N) (EXT_texture_filter_anisotropic).
float GranitePrivate_CalcMiplevelLinear(in GraniteTilesetConstantBuffer tsCB,
        in GraniteStreamingTextureConstantBuffer grSTCB, in gra_Float2 ddxTc, in gra_Float2 ddyTc) {
    gra_Float2 size = Granite_GetTextureDimensions(grSTCB);
    float px = dot(ddxTc * size, ddxTc * size), py = dot(ddyTc * size, ddyTc * size);
    return 0.5 * log2(max(max(px, py), 1e-20));
}
float GranitePrivate_CalcMiplevelAnisotropic(in GraniteTilesetConstantBuffer tsCB,
        in GraniteStreamingTextureConstantBuffer grSTCB, in gra_Float2 ddxTc, in gra_Float2 ddyTc) {
    gra_Float2 size = Granite_GetTextureDimensions(grSTCB);
    float px = length(ddxTc * size), py = length(ddyTc * size);
    float longer = max(max(px, py), 1e-10), shorter = max(min(px, py), 1e-10);
    float anisotropy = min(longer / shorter, exp2(gra_MaxAnisotropyLog2));
    return log2(longer / anisotropy);
}

// Cube-map face selection (the major axis of the direction: 0..5 = +X, -X, +Y, -Y, +Z, -Z) and
// the face's [0, 1] coordinates, as the Direct3D / Vulkan cube-map convention defines them,
// with the gradients of the direction projected onto the face.
void GranitePrivate_CalculateCubemapCoordinates(in gra_Float3 inputTexCoord, in gra_Float3 dVx,
        in gra_Float3 dVy, in GraniteStreamingTextureCubeConstantBuffer transforms, out int faceIdx,
        out gra_Float2 texCoord, out gra_Float2 dX, out gra_Float2 dY) {
    gra_Float3 v = inputTexCoord, a = abs(v);
    gra_Float3 sTM, dVxA, dVyA;  // (s, t, major) of the direction and of its gradients
    if (a.x >= a.y && a.x >= a.z) {
        faceIdx = v.x >= 0 ? 0 : 1;
        sTM = gra_Float3(v.x >= 0 ? -v.z : v.z, -v.y, v.x);
        dVxA = gra_Float3(v.x >= 0 ? -dVx.z : dVx.z, -dVx.y, dVx.x);
        dVyA = gra_Float3(v.x >= 0 ? -dVy.z : dVy.z, -dVy.y, dVy.x);
    } else if (a.y >= a.z) {
        faceIdx = v.y >= 0 ? 2 : 3;
        sTM = gra_Float3(v.x, v.y >= 0 ? v.z : -v.z, v.y);
        dVxA = gra_Float3(dVx.x, v.y >= 0 ? dVx.z : -dVx.z, dVx.y);
        dVyA = gra_Float3(dVy.x, v.y >= 0 ? dVy.z : -dVy.z, dVy.y);
    } else {
        faceIdx = v.z >= 0 ? 4 : 5;
        sTM = gra_Float3(v.z >= 0 ? v.x : -v.x, -v.y, v.z);
        dVxA = gra_Float3(v.z >= 0 ? dVx.x : -dVx.x, -dVx.y, dVx.z);
        dVyA = gra_Float3(v.z >= 0 ? dVy.x : -dVy.x, -dVy.y, dVy.z);
    }
    float m = abs(sTM.z), sign_m = sTM.z >= 0 ? 1 : -1;
    texCoord = sTM.xy / m * 0.5 + 0.5;
    // d(s / |m|) = (ds |m| - s d|m|) / m^2, halved like the coordinates.
    dX = (dVxA.xy * m - sTM.xy * dVxA.z * sign_m) / (m * m) * 0.5;
    dY = (dVyA.xy * m - sTM.xy * dVyA.z * sign_m) / (m * m) * 0.5;
}
void GranitePrivate_CalculateCubemapCoordinates(in gra_Float3 inputTexCoord,
        in GraniteStreamingTextureCubeConstantBuffer transforms, out int faceIdx, out gra_Float2 texCoord,
        out gra_Float2 dX, out gra_Float2 dY) {
    GranitePrivate_CalculateCubemapCoordinates(inputTexCoord, ddx(inputTexCoord), ddy(inputTexCoord),
                                               transforms, faceIdx, texCoord, dX, dY);
}

// Tile ids in the 8-bit channels of the resolve target: (tile x, tile y, level, texture id)
// over 255; unpacking rounds back to the integers.
gra_Float4 GranitePrivate_PackTileId(in gra_Float2 tileXY, in float level, in float textureID) {
    return gra_Float4(tileXY, level, textureID) / 255.0;
}
gra_Float4 Granite_PackTileId(in gra_Float4 unpackedTileID) {
    return unpackedTileID / 255.0;
}
gra_Float4 GranitePrivate_UnpackTileId(in gra_Float4 packedTile) {
    return floor(packedTile * 255.0 + 0.5);
}
// A debug colour per tile: the tile's x, y and level, each modulo 64, over 63.
gra_Float4 Granite_DebugPackedTileId64(in gra_Float4 PackedTile) {
    gra_Float4 id = GranitePrivate_UnpackTileId(PackedTile);
    return gra_Float4(fmod(id.xyz, 64.0) / 63.0, 1);
}

// The tile of the tile set that covers uv at level, packed: what a streaming runtime would read
// back to load it.
gra_Float4 GranitePrivate_MakeResolveOutput(in GraniteTilesetConstantBuffer tsCB, in gra_Float2 tileXY, in float level) {
    return GranitePrivate_PackTileId(tileXY, level, gra_TextureId);
}

// Every lookup's feedback: zero, no tile requested (nothing streams; see the top of
// GraniteShaderLib3.cginc).
gra_Float4 GranitePrivate_NoFeedback() {
    return gra_Float4(0, 0, 0, 0);
}
gra_Float4 GranitePrivate_ResolverPixel(in GraniteTilesetConstantBuffer tsCB, in gra_Float2 inputTexCoord, in float LOD) {
    return GranitePrivate_NoFeedback();
}

// Two resolve outputs in one target: alternate pixels in a checkerboard carry one or the other.
gra_Float4 Granite_MergeResolveOutputs(in gra_Float4 resolve0, in gra_Float4 resolve1, in gra_Float2 pixelLocation) {
    int2 p = int2(floor(pixelLocation));
    return ((p.x + p.y) & 1) == 0 ? resolve0 : resolve1;
}

#if (GRA_HLSL_5 == 1)
// Writes the feedback of one pixel per GRA_RWTEXTURE2D_SCALE square of the screen (the corner
// pixel) into the smaller resolve texture, where the surface is opaque enough (alpha >= 0.5).
void Granite_DitherResolveOutput(in gra_Float4 resolve, in RWTexture2D<GRA_UNORM gra_Float4> resolveTexture,
        in gra_Float2 screenPos, in float alpha) {
    uint2 p = uint2(screenPos);
    if (alpha >= 0.5 && all(p % GRA_RWTEXTURE2D_SCALE == 0))
        resolveTexture[p / GRA_RWTEXTURE2D_SCALE] = resolve;
}
#endif

// Tile borders drawn over sourceColor (debugging): red within 2 % of a tile's edge.
gra_Float4 GranitePrivate_DrawDebugTiles(in gra_Float4 sourceColor, in gra_Float2 textureCoord, in gra_Float2 numPagesOnLevel) {
    gra_Float2 inTile = frac(textureCoord * numPagesOnLevel);
    bool edge = any(inTile < 0.02) || any(inTile > 0.98);
    return edge ? gra_Float4(1, 0, 0, 1) : sourceColor;
}

// Page translation: uv * translation.xy + translation.zw in the cache layer |layer|; the pages
// on the level are the tile set's level-0 tile counts.
gra_Float3 GranitePrivate_TranslateCoord(in GraniteTilesetConstantBuffer tsCB, in gra_Float2 inputTexCoord,
        in gra_Float4 translationData, in int layer, out gra_Float2 numPagesOnLevel) {
    numPagesOnLevel = max(gra_Float2(gra_Level0NumTilesX, gra_Level0NumTilesX * gra_NumTilesYScale), 1);
    return gra_Float3(inputTexCoord * translationData.xy + translationData.zw, layer);
}

// The lookups' results: the coordinates with an identity page translation (scale 1, offset 0).
GraniteLookupData GranitePrivate_MakeLookupData(gra_Float2 uv, gra_Float2 dX, gra_Float2 dY) {
    GraniteLookupData data;
    data.translationTableData = gra_Float4(1, 1, 0, 0);
    data.textureCoordinates = uv;
    data.dX = dX;
    data.dY = dY;
    return data;
}
GraniteLODLookupData GranitePrivate_MakeLODLookupData(gra_Float2 uv, float level) {
    GraniteLODLookupData data;
    data.translationTableData = gra_Float4(1, 1, 0, 0);
    data.textureCoordinates = uv;
    data.cacheLevel = level;
    return data;
}

// The tile-set setters: the HLSL family returns a modified copy, GLSL edits in place.
#if GRA_HLSL_FAMILY
GraniteTilesetConstantBuffer Granite_ApplyResolutionOffset(in GraniteTilesetConstantBuffer INtsCB, in float resolutionOffsetPow2) {
    GraniteTilesetConstantBuffer tsCB = INtsCB;
    gra_LodBiasPow2 *= resolutionOffsetPow2;
    return tsCB;
}
GraniteTilesetConstantBuffer Granite_SetMaxAnisotropy(in GraniteTilesetConstantBuffer INtsCB, in float maxAnisotropyLog2) {
    GraniteTilesetConstantBuffer tsCB = INtsCB;
    gra_MaxAnisotropyLog2 = maxAnisotropyLog2;
    return tsCB;
}
#else
void Granite_ApplyResolutionOffset(inout GraniteTilesetConstantBuffer tsCB, in float resolutionOffsetPow2) {
    gra_LodBiasPow2 *= resolutionOffsetPow2;
}
void Granite_SetMaxAnisotropy(inout GraniteTilesetConstantBuffer tsCB, in float maxAnisotropyLog2) {
    gra_MaxAnisotropyLog2 = maxAnisotropyLog2;
}
#endif

// A normal from a two-channel (BC5-style) normal texel: xy = rg * 2 - 1, scaled, z rebuilt.
gra_Float3 Granite_UnpackNormal(in gra_Float4 PackedNormal, float scale) {
    gra_Float2 xy = (PackedNormal.xy * 2 - 1) * scale;
    return gra_Float3(xy, sqrt(1 - saturate(dot(xy, xy))));
}
gra_Float3 Granite_UnpackNormal(in gra_Float4 PackedNormal) {
    return Granite_UnpackNormal(PackedNormal, 1.0);
}

#include "VarcGraniteSample.cginc"

#endif  // VARC_GRANITE_CORE_INCLUDED
