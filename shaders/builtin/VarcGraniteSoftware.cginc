// SPDX-License-Identifier: Apache-2.0
// varc built-in, part of GraniteShaderLib3.cginc: the software lookups, all through the general lookup of one tile set and
// streaming texture: the address mode applied, an identity page translation, zero feedback (see
// the fallback note at the top of GraniteShaderLib3.cginc). Written for varc.
#include "GraniteShaderLib3.cginc"
#ifndef VARC_GRANITE_SOFTWARE_INCLUDED
#define VARC_GRANITE_SOFTWARE_INCLUDED

int GranitePrivate_Lookup_Software_General(in GraniteTilesetConstantBuffer tsCB,
        in GraniteStreamingTextureConstantBuffer grSTCB, in gra_Float2 inputTexCoord, in float LOD,
        in GraniteTranslationTexture translationTable, out GraniteLODLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    graniteLookupData = GranitePrivate_MakeLODLookupData(GranitePrivate_RepeatUV(inputTexCoord, grSTCB),
            LOD);
    resolveResult = GranitePrivate_NoFeedback();
    return 1;
}

int GranitePrivate_Lookup_Software_General_Anisotropic(in GraniteTilesetConstantBuffer tsCB,
        in GraniteStreamingTextureConstantBuffer grSTCB, in gra_Float2 inputTexCoord,
        in GraniteTranslationTexture translationTable, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult, in gra_Float2 dX, in gra_Float2 dY) {
    graniteLookupData = GranitePrivate_MakeLookupData(GranitePrivate_RepeatUV(inputTexCoord, grSTCB),
            dX, dY);
    resolveResult = GranitePrivate_NoFeedback();
    return 1;
}

int GranitePrivate_Lookup_Software_General_Clamp(in GraniteTilesetConstantBuffer tsCB,
        in GraniteStreamingTextureConstantBuffer grSTCB, in gra_Float2 inputTexCoord, in float LOD,
        in GraniteTranslationTexture translationTable, out GraniteLODLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    graniteLookupData = GranitePrivate_MakeLODLookupData(GranitePrivate_ClampUV(inputTexCoord, grSTCB),
            LOD);
    resolveResult = GranitePrivate_NoFeedback();
    return 1;
}

int GranitePrivate_Lookup_Software_General_Clamp_Anisotropic(in GraniteTilesetConstantBuffer tsCB,
        in GraniteStreamingTextureConstantBuffer grSTCB, in gra_Float2 inputTexCoord,
        in GraniteTranslationTexture translationTable, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult, in gra_Float2 dX, in gra_Float2 dY) {
    graniteLookupData = GranitePrivate_MakeLookupData(GranitePrivate_ClampUV(inputTexCoord, grSTCB), dX,
            dY);
    resolveResult = GranitePrivate_NoFeedback();
    return 1;
}

int GranitePrivate_Lookup_Software_General_Clamp_Linear(in GraniteTilesetConstantBuffer tsCB,
        in GraniteStreamingTextureConstantBuffer grSTCB, in gra_Float2 inputTexCoord,
        in GraniteTranslationTexture translationTable, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult, in gra_Float2 dX, in gra_Float2 dY) {
    graniteLookupData = GranitePrivate_MakeLookupData(GranitePrivate_ClampUV(inputTexCoord, grSTCB), dX,
            dY);
    resolveResult = GranitePrivate_NoFeedback();
    return 1;
}

int GranitePrivate_Lookup_Software_General_Linear(in GraniteTilesetConstantBuffer tsCB,
        in GraniteStreamingTextureConstantBuffer grSTCB, in gra_Float2 inputTexCoord,
        in GraniteTranslationTexture translationTable, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult, in gra_Float2 dX, in gra_Float2 dY) {
    graniteLookupData = GranitePrivate_MakeLookupData(GranitePrivate_RepeatUV(inputTexCoord, grSTCB),
            dX, dY);
    resolveResult = GranitePrivate_NoFeedback();
    return 1;
}

int GranitePrivate_Lookup_Software_General_UDIM(in GraniteTilesetConstantBuffer tsCB,
        in GraniteStreamingTextureConstantBuffer grSTCB, in gra_Float2 inputTexCoord, in float LOD,
        in GraniteTranslationTexture translationTable, out GraniteLODLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    graniteLookupData = GranitePrivate_MakeLODLookupData(GranitePrivate_UdimUV(inputTexCoord, grSTCB),
            LOD);
    resolveResult = GranitePrivate_NoFeedback();
    return 1;
}

int GranitePrivate_Lookup_Software_General_UDIM_Anisotropic(in GraniteTilesetConstantBuffer tsCB,
        in GraniteStreamingTextureConstantBuffer grSTCB, in gra_Float2 inputTexCoord,
        in GraniteTranslationTexture translationTable, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult, in gra_Float2 dX, in gra_Float2 dY) {
    graniteLookupData = GranitePrivate_MakeLookupData(GranitePrivate_UdimUV(inputTexCoord, grSTCB), dX,
            dY);
    resolveResult = GranitePrivate_NoFeedback();
    return 1;
}

int GranitePrivate_Lookup_Software_General_UDIM_Linear(in GraniteTilesetConstantBuffer tsCB,
        in GraniteStreamingTextureConstantBuffer grSTCB, in gra_Float2 inputTexCoord,
        in GraniteTranslationTexture translationTable, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult, in gra_Float2 dX, in gra_Float2 dY) {
    graniteLookupData = GranitePrivate_MakeLookupData(GranitePrivate_UdimUV(inputTexCoord, grSTCB), dX,
            dY);
    resolveResult = GranitePrivate_NoFeedback();
    return 1;
}

int GranitePrivate_Lookup_PreTransformed_Software(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, float LOD, in GraniteTranslationTexture translationTable,
        out GraniteLODLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General(grCB.tilesetBuffer, grCB.streamingTextureBuffer,
            inputTexCoord, LOD, translationTable, graniteLookupData, resolveResult);
}

int GranitePrivate_Lookup_PreTransformed_Software_Anisotropic(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in GraniteTranslationTexture translationTable,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_Anisotropic(grCB.tilesetBuffer,
            grCB.streamingTextureBuffer, inputTexCoord, translationTable, graniteLookupData,
            resolveResult, ddx(inputTexCoord), ddy(inputTexCoord));
}

int GranitePrivate_Lookup_PreTransformed_Software_Anisotropic(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in gra_Float2 ddX, in gra_Float2 ddY,
        in GraniteTranslationTexture translationTable, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_Anisotropic(grCB.tilesetBuffer,
            grCB.streamingTextureBuffer, inputTexCoord, translationTable, graniteLookupData,
            resolveResult, ddX, ddY);
}

int GranitePrivate_Lookup_PreTransformed_Software_Clamp(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, float LOD, in GraniteTranslationTexture translationTable,
        out GraniteLODLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_Clamp(grCB.tilesetBuffer, grCB.streamingTextureBuffer,
            inputTexCoord, LOD, translationTable, graniteLookupData, resolveResult);
}

int GranitePrivate_Lookup_PreTransformed_Software_Clamp_Anisotropic(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in GraniteTranslationTexture translationTable,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_Clamp_Anisotropic(grCB.tilesetBuffer,
            grCB.streamingTextureBuffer, inputTexCoord, translationTable, graniteLookupData,
            resolveResult, ddx(inputTexCoord), ddy(inputTexCoord));
}

int GranitePrivate_Lookup_PreTransformed_Software_Clamp_Anisotropic(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in gra_Float2 ddX, in gra_Float2 ddY,
        in GraniteTranslationTexture translationTable, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_Clamp_Anisotropic(grCB.tilesetBuffer,
            grCB.streamingTextureBuffer, inputTexCoord, translationTable, graniteLookupData,
            resolveResult, ddX, ddY);
}

int GranitePrivate_Lookup_PreTransformed_Software_Clamp_Linear(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in GraniteTranslationTexture translationTable,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_Clamp_Linear(grCB.tilesetBuffer,
            grCB.streamingTextureBuffer, inputTexCoord, translationTable, graniteLookupData,
            resolveResult, ddx(inputTexCoord), ddy(inputTexCoord));
}

int GranitePrivate_Lookup_PreTransformed_Software_Clamp_Linear(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in gra_Float2 ddX, in gra_Float2 ddY,
        in GraniteTranslationTexture translationTable, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_Clamp_Linear(grCB.tilesetBuffer,
            grCB.streamingTextureBuffer, inputTexCoord, translationTable, graniteLookupData,
            resolveResult, ddX, ddY);
}

int GranitePrivate_Lookup_PreTransformed_Software_Linear(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in GraniteTranslationTexture translationTable,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_Linear(grCB.tilesetBuffer,
            grCB.streamingTextureBuffer, inputTexCoord, translationTable, graniteLookupData,
            resolveResult, ddx(inputTexCoord), ddy(inputTexCoord));
}

int GranitePrivate_Lookup_PreTransformed_Software_Linear(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in gra_Float2 ddX, in gra_Float2 ddY,
        in GraniteTranslationTexture translationTable, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_Linear(grCB.tilesetBuffer,
            grCB.streamingTextureBuffer, inputTexCoord, translationTable, graniteLookupData,
            resolveResult, ddX, ddY);
}

int GranitePrivate_Lookup_PreTransformed_Software_UDIM(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, float LOD, in GraniteTranslationTexture translationTable,
        out GraniteLODLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_UDIM(grCB.tilesetBuffer, grCB.streamingTextureBuffer,
            inputTexCoord, LOD, translationTable, graniteLookupData, resolveResult);
}

int GranitePrivate_Lookup_PreTransformed_Software_UDIM_Anisotropic(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in GraniteTranslationTexture translationTable,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_UDIM_Anisotropic(grCB.tilesetBuffer,
            grCB.streamingTextureBuffer, inputTexCoord, translationTable, graniteLookupData,
            resolveResult, ddx(inputTexCoord), ddy(inputTexCoord));
}

int GranitePrivate_Lookup_PreTransformed_Software_UDIM_Anisotropic(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in gra_Float2 ddX, in gra_Float2 ddY,
        in GraniteTranslationTexture translationTable, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_UDIM_Anisotropic(grCB.tilesetBuffer,
            grCB.streamingTextureBuffer, inputTexCoord, translationTable, graniteLookupData,
            resolveResult, ddX, ddY);
}

int GranitePrivate_Lookup_PreTransformed_Software_UDIM_Linear(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in GraniteTranslationTexture translationTable,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_UDIM_Linear(grCB.tilesetBuffer,
            grCB.streamingTextureBuffer, inputTexCoord, translationTable, graniteLookupData,
            resolveResult, ddx(inputTexCoord), ddy(inputTexCoord));
}

int GranitePrivate_Lookup_PreTransformed_Software_UDIM_Linear(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in gra_Float2 ddX, in gra_Float2 ddY,
        in GraniteTranslationTexture translationTable, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_UDIM_Linear(grCB.tilesetBuffer,
            grCB.streamingTextureBuffer, inputTexCoord, translationTable, graniteLookupData,
            resolveResult, ddX, ddY);
}

int GranitePrivate_Lookup_Software(in GraniteConstantBuffers grCB, in gra_Float2 inputTexCoord,
        float LOD, in GraniteTranslationTexture translationTable,
        out GraniteLODLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General(grCB.tilesetBuffer, grCB.streamingTextureBuffer,
            inputTexCoord, LOD, translationTable, graniteLookupData, resolveResult);
}

int GranitePrivate_Lookup_Software_Anisotropic(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in GraniteTranslationTexture translationTable,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_Anisotropic(grCB.tilesetBuffer,
            grCB.streamingTextureBuffer, inputTexCoord, translationTable, graniteLookupData,
            resolveResult, ddx(inputTexCoord), ddy(inputTexCoord));
}

int GranitePrivate_Lookup_Software_Anisotropic(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in gra_Float2 ddX, in gra_Float2 ddY,
        in GraniteTranslationTexture translationTable, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_Anisotropic(grCB.tilesetBuffer,
            grCB.streamingTextureBuffer, inputTexCoord, translationTable, graniteLookupData,
            resolveResult, ddX, ddY);
}

int GranitePrivate_Lookup_Software_Clamp(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, float LOD, in GraniteTranslationTexture translationTable,
        out GraniteLODLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_Clamp(grCB.tilesetBuffer, grCB.streamingTextureBuffer,
            inputTexCoord, LOD, translationTable, graniteLookupData, resolveResult);
}

int GranitePrivate_Lookup_Software_Clamp_Anisotropic(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in GraniteTranslationTexture translationTable,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_Clamp_Anisotropic(grCB.tilesetBuffer,
            grCB.streamingTextureBuffer, inputTexCoord, translationTable, graniteLookupData,
            resolveResult, ddx(inputTexCoord), ddy(inputTexCoord));
}

int GranitePrivate_Lookup_Software_Clamp_Anisotropic(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in gra_Float2 ddX, in gra_Float2 ddY,
        in GraniteTranslationTexture translationTable, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_Clamp_Anisotropic(grCB.tilesetBuffer,
            grCB.streamingTextureBuffer, inputTexCoord, translationTable, graniteLookupData,
            resolveResult, ddX, ddY);
}

int GranitePrivate_Lookup_Software_Clamp_Linear(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in GraniteTranslationTexture translationTable,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_Clamp_Linear(grCB.tilesetBuffer,
            grCB.streamingTextureBuffer, inputTexCoord, translationTable, graniteLookupData,
            resolveResult, ddx(inputTexCoord), ddy(inputTexCoord));
}

int GranitePrivate_Lookup_Software_Clamp_Linear(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in gra_Float2 ddX, in gra_Float2 ddY,
        in GraniteTranslationTexture translationTable, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_Clamp_Linear(grCB.tilesetBuffer,
            grCB.streamingTextureBuffer, inputTexCoord, translationTable, graniteLookupData,
            resolveResult, ddX, ddY);
}

int GranitePrivate_Lookup_Software_Linear(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in GraniteTranslationTexture translationTable,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_Linear(grCB.tilesetBuffer,
            grCB.streamingTextureBuffer, inputTexCoord, translationTable, graniteLookupData,
            resolveResult, ddx(inputTexCoord), ddy(inputTexCoord));
}

int GranitePrivate_Lookup_Software_Linear(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in gra_Float2 ddX, in gra_Float2 ddY,
        in GraniteTranslationTexture translationTable, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_Linear(grCB.tilesetBuffer,
            grCB.streamingTextureBuffer, inputTexCoord, translationTable, graniteLookupData,
            resolveResult, ddX, ddY);
}

int GranitePrivate_Lookup_Software_UDIM(in GraniteConstantBuffers grCB, in gra_Float2 inputTexCoord,
        float LOD, in GraniteTranslationTexture translationTable,
        out GraniteLODLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_UDIM(grCB.tilesetBuffer, grCB.streamingTextureBuffer,
            inputTexCoord, LOD, translationTable, graniteLookupData, resolveResult);
}

int GranitePrivate_Lookup_Software_UDIM_Anisotropic(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in GraniteTranslationTexture translationTable,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_UDIM_Anisotropic(grCB.tilesetBuffer,
            grCB.streamingTextureBuffer, inputTexCoord, translationTable, graniteLookupData,
            resolveResult, ddx(inputTexCoord), ddy(inputTexCoord));
}

int GranitePrivate_Lookup_Software_UDIM_Anisotropic(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in gra_Float2 ddX, in gra_Float2 ddY,
        in GraniteTranslationTexture translationTable, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_UDIM_Anisotropic(grCB.tilesetBuffer,
            grCB.streamingTextureBuffer, inputTexCoord, translationTable, graniteLookupData,
            resolveResult, ddX, ddY);
}

int GranitePrivate_Lookup_Software_UDIM_Linear(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in GraniteTranslationTexture translationTable,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_UDIM_Linear(grCB.tilesetBuffer,
            grCB.streamingTextureBuffer, inputTexCoord, translationTable, graniteLookupData,
            resolveResult, ddx(inputTexCoord), ddy(inputTexCoord));
}

int GranitePrivate_Lookup_Software_UDIM_Linear(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in gra_Float2 ddX, in gra_Float2 ddY,
        in GraniteTranslationTexture translationTable, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_General_UDIM_Linear(grCB.tilesetBuffer,
            grCB.streamingTextureBuffer, inputTexCoord, translationTable, graniteLookupData,
            resolveResult, ddX, ddY);
}
#endif  // VARC_GRANITE_SOFTWARE_INCLUDED
