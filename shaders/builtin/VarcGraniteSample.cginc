// SPDX-License-Identifier: Apache-2.0
// varc built-in, part of GraniteShaderLib3.cginc: sampling the cache textures and the translation
// table, and Granite_Sample, which reads a lookup's texel (see the fallback note at the top of
// GraniteShaderLib3.cginc: the cache is the whole texture). Written for varc.
#include "GraniteShaderLib3.cginc"
#ifndef VARC_GRANITE_SAMPLE_INCLUDED
#define VARC_GRANITE_SAMPLE_INCLUDED

#if ((GRA_HLSL_5 == 1) || (GRA_HLSL_4 == 1))
gra_Float4 GranitePrivate_SampleLevel_Translation(in GraniteTranslationTexture tex, in gra_Float2 texCoord, in float level) {
    return tex.Texture.SampleLevel(tex.Sampler, texCoord, level);
}
#if (GRA_LOAD_INSTR == 1)
gra_Float4 GranitePrivate_Load(in GraniteTranslationTexture tex, in gra_Int3 location) {
    return tex.Texture.Load(location);
}
#endif
#if (GRA_TEXTURE_ARRAY_SUPPORT == 1)
gra_Float4 GranitePrivate_SampleArray(in GraniteCacheTexture tex, in gra_Float3 texCoord) {
    return tex.TextureArray.Sample(tex.Sampler, texCoord);
}
gra_Float4 GranitePrivate_SampleGradArray(in GraniteCacheTexture tex, in gra_Float3 texCoord, in gra_Float2 dX, in gra_Float2 dY) {
    return tex.TextureArray.SampleGrad(tex.Sampler, texCoord, dX, dY);
}
gra_Float4 GranitePrivate_SampleLevelArray(in GraniteCacheTexture tex, in gra_Float3 texCoord, in float level) {
    return tex.TextureArray.SampleLevel(tex.Sampler, texCoord, level);
}
#else
gra_Float4 GranitePrivate_Sample(in GraniteCacheTexture tex, in gra_Float2 texCoord) {
    return tex.Texture.Sample(tex.Sampler, texCoord);
}
gra_Float4 GranitePrivate_SampleGrad(in GraniteCacheTexture tex, in gra_Float2 texCoord, in gra_Float2 dX, in gra_Float2 dY) {
    return tex.Texture.SampleGrad(tex.Sampler, texCoord, dX, dY);
}
gra_Float4 GranitePrivate_SampleLevel(in GraniteCacheTexture tex, in gra_Float2 texCoord, in float level) {
    return tex.Texture.SampleLevel(tex.Sampler, texCoord, level);
}
#endif
#endif

// The cache texel of a lookup in layer |layer|: with the lookup's gradients (scaled by the page
// translation) or at its level. Always resident: returns 1.
int Granite_Sample_Internal(in GraniteTilesetConstantBuffer tsCB, in GraniteLookupData graniteLookupData,
        in GraniteCacheTexture cacheTexture, in int layer, out gra_Float4 result) {
    gra_Float2 numPages;
    gra_Float4 t = graniteLookupData.translationTableData;
    gra_Float3 coord = GranitePrivate_TranslateCoord(tsCB, graniteLookupData.textureCoordinates, t, layer, numPages);
#if (GRA_TEXTURE_ARRAY_SUPPORT == 1)
    result = GranitePrivate_SampleGradArray(cacheTexture, coord, graniteLookupData.dX * t.xy, graniteLookupData.dY * t.xy);
#else
    result = GranitePrivate_SampleGrad(cacheTexture, coord.xy, graniteLookupData.dX * t.xy, graniteLookupData.dY * t.xy);
#endif
#if GRA_DEBUG_TILES
    result = GranitePrivate_DrawDebugTiles(result, graniteLookupData.textureCoordinates, numPages);
#endif
    return 1;
}
// Unity's spelling of the level-lookup variant.
int Granite_Sample_Interal(in GraniteTilesetConstantBuffer tsCB, in GraniteLODLookupData graniteLookupData,
        in GraniteCacheTexture cacheTexture, in int layer, out gra_Float4 result) {
    gra_Float2 numPages;
    gra_Float4 t = graniteLookupData.translationTableData;
    gra_Float3 coord = GranitePrivate_TranslateCoord(tsCB, graniteLookupData.textureCoordinates, t, layer, numPages);
#if (GRA_TEXTURE_ARRAY_SUPPORT == 1)
    result = GranitePrivate_SampleLevelArray(cacheTexture, coord, graniteLookupData.cacheLevel);
#else
    result = GranitePrivate_SampleLevel(cacheTexture, coord.xy, graniteLookupData.cacheLevel);
#endif
#if GRA_DEBUG_TILES
    result = GranitePrivate_DrawDebugTiles(result, graniteLookupData.textureCoordinates, numPages);
#endif
    return 1;
}
// High-quality sampling: the hardware's anisotropic filtering of the whole texture already is.
int Granite_Sample_HQ_Internal(in GraniteTilesetConstantBuffer tsCB, in GraniteLookupData graniteLookupData,
        in GraniteCacheTexture cacheTexture, in int layer, out gra_Float4 result) {
    return Granite_Sample_Internal(tsCB, graniteLookupData, cacheTexture, layer, result);
}

int Granite_Sample(in GraniteConstantBuffers grCB, in GraniteLookupData graniteLookupData,
        in GraniteCacheTexture cacheTexture, in int layer, out gra_Float4 result) {
    return Granite_Sample_Internal(grCB.tilesetBuffer, graniteLookupData, cacheTexture, layer, result);
}
int Granite_Sample(in GraniteConstantBuffers grCB, in GraniteLODLookupData graniteLookupData,
        in GraniteCacheTexture cacheTexture, in int layer, out gra_Float4 result) {
    return Granite_Sample_Interal(grCB.tilesetBuffer, graniteLookupData, cacheTexture, layer, result);
}
int Granite_Sample(in GraniteCubeConstantBuffers grCB, in GraniteLookupData graniteLookupData,
        in GraniteCacheTexture cacheTexture, in int layer, out gra_Float4 result) {
    return Granite_Sample_Internal(grCB.tilesetBuffer, graniteLookupData, cacheTexture, layer, result);
}
int Granite_Sample(in GraniteCubeConstantBuffers grCB, in GraniteLODLookupData graniteLookupData,
        in GraniteCacheTexture cacheTexture, in int layer, out gra_Float4 result) {
    return Granite_Sample_Interal(grCB.tilesetBuffer, graniteLookupData, cacheTexture, layer, result);
}
int Granite_Sample_HQ(in GraniteConstantBuffers grCB, in GraniteLookupData graniteLookupData,
        in GraniteCacheTexture cacheTexture, in int layer, out gra_Float4 result) {
    return Granite_Sample_HQ_Internal(grCB.tilesetBuffer, graniteLookupData, cacheTexture, layer, result);
}
int Granite_Sample_HQ(in GraniteCubeConstantBuffers grCB, in GraniteLookupData graniteLookupData,
        in GraniteCacheTexture cacheTexture, in int layer, out gra_Float4 result) {
    return Granite_Sample_HQ_Internal(grCB.tilesetBuffer, graniteLookupData, cacheTexture, layer, result);
}

#endif  // VARC_GRANITE_SAMPLE_INCLUDED
