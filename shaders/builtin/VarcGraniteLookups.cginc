// SPDX-License-Identifier: Apache-2.0
// varc built-in, part of GraniteShaderLib3.cginc: the public lookups (2D, cube faces, dynamic UDIM
// choice), each the software lookup of its variant (see the fallback note at the top of
// GraniteShaderLib3.cginc). Written for varc.
#include "GraniteShaderLib3.cginc"
#ifndef VARC_GRANITE_LOOKUPS_INCLUDED
#define VARC_GRANITE_LOOKUPS_INCLUDED

int Granite_Lookup(in GraniteConstantBuffers grCB, in GraniteTranslationTexture translationTable,
        in gra_Float2 inputTexCoord, in float LOD, out GraniteLODLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software(grCB, inputTexCoord, LOD, translationTable, graniteLookupData,
            resolveResult);
}

int Granite_Lookup_Anisotropic(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord,
        in gra_Float2 ddX, in gra_Float2 ddY, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_Anisotropic(grCB, inputTexCoord, ddX, ddY, translationTable,
            graniteLookupData, resolveResult);
}

int Granite_Lookup_Anisotropic(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_Anisotropic(grCB, inputTexCoord, translationTable,
            graniteLookupData, resolveResult);
}

int Granite_Lookup_Clamp(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord, in float LOD,
        out GraniteLODLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_Clamp(grCB, inputTexCoord, LOD, translationTable,
            graniteLookupData, resolveResult);
}

int Granite_Lookup_Clamp_Anisotropic(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord,
        in gra_Float2 ddX, in gra_Float2 ddY, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_Clamp_Anisotropic(grCB, inputTexCoord, ddX, ddY,
            translationTable, graniteLookupData, resolveResult);
}

int Granite_Lookup_Clamp_Anisotropic(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_Clamp_Anisotropic(grCB, inputTexCoord, translationTable,
            graniteLookupData, resolveResult);
}

int Granite_Lookup_Clamp_Linear(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord,
        in gra_Float2 ddX, in gra_Float2 ddY, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_Clamp_Linear(grCB, inputTexCoord, ddX, ddY, translationTable,
            graniteLookupData, resolveResult);
}

int Granite_Lookup_Clamp_Linear(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_Clamp_Linear(grCB, inputTexCoord, translationTable,
            graniteLookupData, resolveResult);
}

int Granite_Lookup_Linear(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord,
        in gra_Float2 ddX, in gra_Float2 ddY, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_Linear(grCB, inputTexCoord, ddX, ddY, translationTable,
            graniteLookupData, resolveResult);
}

int Granite_Lookup_Linear(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_Linear(grCB, inputTexCoord, translationTable,
            graniteLookupData, resolveResult);
}

int Granite_Lookup_PreTransformed(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord, in float LOD,
        out GraniteLODLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_PreTransformed_Software(grCB, inputTexCoord, LOD, translationTable,
            graniteLookupData, resolveResult);
}

int Granite_Lookup_PreTransformed_Anisotropic(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord,
        in gra_Float2 ddX, in gra_Float2 ddY, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_PreTransformed_Software_Anisotropic(grCB, inputTexCoord, ddX, ddY,
            translationTable, graniteLookupData, resolveResult);
}

int Granite_Lookup_PreTransformed_Anisotropic(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_PreTransformed_Software_Anisotropic(grCB, inputTexCoord,
            translationTable, graniteLookupData, resolveResult);
}

int Granite_Lookup_PreTransformed_Clamp(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord, in float LOD,
        out GraniteLODLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_PreTransformed_Software_Clamp(grCB, inputTexCoord, LOD,
            translationTable, graniteLookupData, resolveResult);
}

int Granite_Lookup_PreTransformed_Clamp_Anisotropic(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord,
        in gra_Float2 ddX, in gra_Float2 ddY, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_PreTransformed_Software_Clamp_Anisotropic(grCB, inputTexCoord, ddX,
            ddY, translationTable, graniteLookupData, resolveResult);
}

int Granite_Lookup_PreTransformed_Clamp_Anisotropic(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_PreTransformed_Software_Clamp_Anisotropic(grCB, inputTexCoord,
            translationTable, graniteLookupData, resolveResult);
}

int Granite_Lookup_PreTransformed_Clamp_Linear(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord,
        in gra_Float2 ddX, in gra_Float2 ddY, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_PreTransformed_Software_Clamp_Linear(grCB, inputTexCoord, ddX, ddY,
            translationTable, graniteLookupData, resolveResult);
}

int Granite_Lookup_PreTransformed_Clamp_Linear(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_PreTransformed_Software_Clamp_Linear(grCB, inputTexCoord,
            translationTable, graniteLookupData, resolveResult);
}

int Granite_Lookup_PreTransformed_Linear(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord,
        in gra_Float2 ddX, in gra_Float2 ddY, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_PreTransformed_Software_Linear(grCB, inputTexCoord, ddX, ddY,
            translationTable, graniteLookupData, resolveResult);
}

int Granite_Lookup_PreTransformed_Linear(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_PreTransformed_Software_Linear(grCB, inputTexCoord, translationTable,
            graniteLookupData, resolveResult);
}

int Granite_Lookup_PreTransformed_UDIM(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord, in float LOD,
        out GraniteLODLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_PreTransformed_Software_UDIM(grCB, inputTexCoord, LOD,
            translationTable, graniteLookupData, resolveResult);
}

int Granite_Lookup_PreTransformed_UDIM_Anisotropic(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord,
        in gra_Float2 ddX, in gra_Float2 ddY, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_PreTransformed_Software_UDIM_Anisotropic(grCB, inputTexCoord, ddX, ddY,
            translationTable, graniteLookupData, resolveResult);
}

int Granite_Lookup_PreTransformed_UDIM_Anisotropic(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_PreTransformed_Software_UDIM_Anisotropic(grCB, inputTexCoord,
            translationTable, graniteLookupData, resolveResult);
}

int Granite_Lookup_PreTransformed_UDIM_Linear(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord,
        in gra_Float2 ddX, in gra_Float2 ddY, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_PreTransformed_Software_UDIM_Linear(grCB, inputTexCoord, ddX, ddY,
            translationTable, graniteLookupData, resolveResult);
}

int Granite_Lookup_PreTransformed_UDIM_Linear(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_PreTransformed_Software_UDIM_Linear(grCB, inputTexCoord,
            translationTable, graniteLookupData, resolveResult);
}

int Granite_Lookup_UDIM(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord, in float LOD,
        out GraniteLODLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_UDIM(grCB, inputTexCoord, LOD, translationTable,
            graniteLookupData, resolveResult);
}

int Granite_Lookup_UDIM_Anisotropic(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord,
        in gra_Float2 ddX, in gra_Float2 ddY, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_UDIM_Anisotropic(grCB, inputTexCoord, ddX, ddY,
            translationTable, graniteLookupData, resolveResult);
}

int Granite_Lookup_UDIM_Anisotropic(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_UDIM_Anisotropic(grCB, inputTexCoord, translationTable,
            graniteLookupData, resolveResult);
}

int Granite_Lookup_UDIM_Linear(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord,
        in gra_Float2 ddX, in gra_Float2 ddY, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_UDIM_Linear(grCB, inputTexCoord, ddX, ddY, translationTable,
            graniteLookupData, resolveResult);
}

int Granite_Lookup_UDIM_Linear(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return GranitePrivate_Lookup_Software_UDIM_Linear(grCB, inputTexCoord, translationTable,
            graniteLookupData, resolveResult);
}

int Granite_Lookup_Cube(in GraniteCubeConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float3 inputTexCoord, in float LOD,
        out GraniteLODLookupData graniteLookupData, out gra_Float4 resolveResult) {
    int faceIdx;
    gra_Float2 texCoord, dX, dY;
    GranitePrivate_CalculateCubemapCoordinates(inputTexCoord, gra_Float3(0, 0, 0), gra_Float3(0, 0, 0),
            grCB.streamingTextureCubeBuffer, faceIdx, texCoord, dX, dY);
    return GranitePrivate_Lookup_Software_General(grCB.tilesetBuffer,
            grCB.streamingTextureCubeBuffer.data[faceIdx], texCoord, LOD, translationTable,
            graniteLookupData, resolveResult);
}

int Granite_Lookup_Cube_Anisotropic(in GraniteCubeConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float3 inputTexCoord,
        in gra_Float3 ddX, in gra_Float3 ddY, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    int faceIdx;
    gra_Float2 texCoord, dX, dY;
    GranitePrivate_CalculateCubemapCoordinates(inputTexCoord, ddX, ddY, grCB.streamingTextureCubeBuffer,
            faceIdx, texCoord, dX, dY);
    return GranitePrivate_Lookup_Software_General_Anisotropic(grCB.tilesetBuffer,
            grCB.streamingTextureCubeBuffer.data[faceIdx], texCoord, translationTable,
            graniteLookupData, resolveResult, dX, dY);
}

int Granite_Lookup_Cube_Anisotropic(in GraniteCubeConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float3 inputTexCoord,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    int faceIdx;
    gra_Float2 texCoord, dX, dY;
    GranitePrivate_CalculateCubemapCoordinates(inputTexCoord, ddx(inputTexCoord), ddy(inputTexCoord),
            grCB.streamingTextureCubeBuffer, faceIdx, texCoord, dX, dY);
    return GranitePrivate_Lookup_Software_General_Anisotropic(grCB.tilesetBuffer,
            grCB.streamingTextureCubeBuffer.data[faceIdx], texCoord, translationTable,
            graniteLookupData, resolveResult, dX, dY);
}

int Granite_Lookup_Cube_Clamp(in GraniteCubeConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float3 inputTexCoord, in float LOD,
        out GraniteLODLookupData graniteLookupData, out gra_Float4 resolveResult) {
    int faceIdx;
    gra_Float2 texCoord, dX, dY;
    GranitePrivate_CalculateCubemapCoordinates(inputTexCoord, gra_Float3(0, 0, 0), gra_Float3(0, 0, 0),
            grCB.streamingTextureCubeBuffer, faceIdx, texCoord, dX, dY);
    return GranitePrivate_Lookup_Software_General_Clamp(grCB.tilesetBuffer,
            grCB.streamingTextureCubeBuffer.data[faceIdx], texCoord, LOD, translationTable,
            graniteLookupData, resolveResult);
}

int Granite_Lookup_Cube_Clamp_Anisotropic(in GraniteCubeConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float3 inputTexCoord,
        in gra_Float3 ddX, in gra_Float3 ddY, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    int faceIdx;
    gra_Float2 texCoord, dX, dY;
    GranitePrivate_CalculateCubemapCoordinates(inputTexCoord, ddX, ddY, grCB.streamingTextureCubeBuffer,
            faceIdx, texCoord, dX, dY);
    return GranitePrivate_Lookup_Software_General_Clamp_Anisotropic(grCB.tilesetBuffer,
            grCB.streamingTextureCubeBuffer.data[faceIdx], texCoord, translationTable,
            graniteLookupData, resolveResult, dX, dY);
}

int Granite_Lookup_Cube_Clamp_Anisotropic(in GraniteCubeConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float3 inputTexCoord,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    int faceIdx;
    gra_Float2 texCoord, dX, dY;
    GranitePrivate_CalculateCubemapCoordinates(inputTexCoord, ddx(inputTexCoord), ddy(inputTexCoord),
            grCB.streamingTextureCubeBuffer, faceIdx, texCoord, dX, dY);
    return GranitePrivate_Lookup_Software_General_Clamp_Anisotropic(grCB.tilesetBuffer,
            grCB.streamingTextureCubeBuffer.data[faceIdx], texCoord, translationTable,
            graniteLookupData, resolveResult, dX, dY);
}

int Granite_Lookup_Cube_Clamp_Linear(in GraniteCubeConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float3 inputTexCoord,
        in gra_Float3 ddX, in gra_Float3 ddY, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    int faceIdx;
    gra_Float2 texCoord, dX, dY;
    GranitePrivate_CalculateCubemapCoordinates(inputTexCoord, ddX, ddY, grCB.streamingTextureCubeBuffer,
            faceIdx, texCoord, dX, dY);
    return GranitePrivate_Lookup_Software_General_Clamp_Linear(grCB.tilesetBuffer,
            grCB.streamingTextureCubeBuffer.data[faceIdx], texCoord, translationTable,
            graniteLookupData, resolveResult, dX, dY);
}

int Granite_Lookup_Cube_Clamp_Linear(in GraniteCubeConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float3 inputTexCoord,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    int faceIdx;
    gra_Float2 texCoord, dX, dY;
    GranitePrivate_CalculateCubemapCoordinates(inputTexCoord, ddx(inputTexCoord), ddy(inputTexCoord),
            grCB.streamingTextureCubeBuffer, faceIdx, texCoord, dX, dY);
    return GranitePrivate_Lookup_Software_General_Clamp_Linear(grCB.tilesetBuffer,
            grCB.streamingTextureCubeBuffer.data[faceIdx], texCoord, translationTable,
            graniteLookupData, resolveResult, dX, dY);
}

int Granite_Lookup_Cube_Linear(in GraniteCubeConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float3 inputTexCoord,
        in gra_Float3 ddX, in gra_Float3 ddY, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    int faceIdx;
    gra_Float2 texCoord, dX, dY;
    GranitePrivate_CalculateCubemapCoordinates(inputTexCoord, ddX, ddY, grCB.streamingTextureCubeBuffer,
            faceIdx, texCoord, dX, dY);
    return GranitePrivate_Lookup_Software_General_Linear(grCB.tilesetBuffer,
            grCB.streamingTextureCubeBuffer.data[faceIdx], texCoord, translationTable,
            graniteLookupData, resolveResult, dX, dY);
}

int Granite_Lookup_Cube_Linear(in GraniteCubeConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float3 inputTexCoord,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    int faceIdx;
    gra_Float2 texCoord, dX, dY;
    GranitePrivate_CalculateCubemapCoordinates(inputTexCoord, ddx(inputTexCoord), ddy(inputTexCoord),
            grCB.streamingTextureCubeBuffer, faceIdx, texCoord, dX, dY);
    return GranitePrivate_Lookup_Software_General_Linear(grCB.tilesetBuffer,
            grCB.streamingTextureCubeBuffer.data[faceIdx], texCoord, translationTable,
            graniteLookupData, resolveResult, dX, dY);
}

int Granite_Lookup_Cube_UDIM(in GraniteCubeConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float3 inputTexCoord, in float LOD,
        out GraniteLODLookupData graniteLookupData, out gra_Float4 resolveResult) {
    int faceIdx;
    gra_Float2 texCoord, dX, dY;
    GranitePrivate_CalculateCubemapCoordinates(inputTexCoord, gra_Float3(0, 0, 0), gra_Float3(0, 0, 0),
            grCB.streamingTextureCubeBuffer, faceIdx, texCoord, dX, dY);
    return GranitePrivate_Lookup_Software_General_UDIM(grCB.tilesetBuffer,
            grCB.streamingTextureCubeBuffer.data[faceIdx], texCoord, LOD, translationTable,
            graniteLookupData, resolveResult);
}

int Granite_Lookup_Cube_UDIM_Anisotropic(in GraniteCubeConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float3 inputTexCoord,
        in gra_Float3 ddX, in gra_Float3 ddY, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    int faceIdx;
    gra_Float2 texCoord, dX, dY;
    GranitePrivate_CalculateCubemapCoordinates(inputTexCoord, ddX, ddY, grCB.streamingTextureCubeBuffer,
            faceIdx, texCoord, dX, dY);
    return GranitePrivate_Lookup_Software_General_UDIM_Anisotropic(grCB.tilesetBuffer,
            grCB.streamingTextureCubeBuffer.data[faceIdx], texCoord, translationTable,
            graniteLookupData, resolveResult, dX, dY);
}

int Granite_Lookup_Cube_UDIM_Anisotropic(in GraniteCubeConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float3 inputTexCoord,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    int faceIdx;
    gra_Float2 texCoord, dX, dY;
    GranitePrivate_CalculateCubemapCoordinates(inputTexCoord, ddx(inputTexCoord), ddy(inputTexCoord),
            grCB.streamingTextureCubeBuffer, faceIdx, texCoord, dX, dY);
    return GranitePrivate_Lookup_Software_General_UDIM_Anisotropic(grCB.tilesetBuffer,
            grCB.streamingTextureCubeBuffer.data[faceIdx], texCoord, translationTable,
            graniteLookupData, resolveResult, dX, dY);
}

int Granite_Lookup_Cube_UDIM_Linear(in GraniteCubeConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float3 inputTexCoord,
        in gra_Float3 ddX, in gra_Float3 ddY, out GraniteLookupData graniteLookupData,
        out gra_Float4 resolveResult) {
    int faceIdx;
    gra_Float2 texCoord, dX, dY;
    GranitePrivate_CalculateCubemapCoordinates(inputTexCoord, ddX, ddY, grCB.streamingTextureCubeBuffer,
            faceIdx, texCoord, dX, dY);
    return GranitePrivate_Lookup_Software_General_UDIM_Linear(grCB.tilesetBuffer,
            grCB.streamingTextureCubeBuffer.data[faceIdx], texCoord, translationTable,
            graniteLookupData, resolveResult, dX, dY);
}

int Granite_Lookup_Cube_UDIM_Linear(in GraniteCubeConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float3 inputTexCoord,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    int faceIdx;
    gra_Float2 texCoord, dX, dY;
    GranitePrivate_CalculateCubemapCoordinates(inputTexCoord, ddx(inputTexCoord), ddy(inputTexCoord),
            grCB.streamingTextureCubeBuffer, faceIdx, texCoord, dX, dY);
    return GranitePrivate_Lookup_Software_General_UDIM_Linear(grCB.tilesetBuffer,
            grCB.streamingTextureCubeBuffer.data[faceIdx], texCoord, translationTable,
            graniteLookupData, resolveResult, dX, dY);
}

int Granite_Lookup_Dynamic_Anisotropic(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord, in bool asUDIM,
        in float LOD, out GraniteLODLookupData graniteLODLookupData, out gra_Float4 resolveResult) {
    return asUDIM ? Granite_Lookup_UDIM(grCB, translationTable, inputTexCoord, LOD,
            graniteLODLookupData, resolveResult) : Granite_Lookup(grCB, translationTable, inputTexCoord,
            LOD, graniteLODLookupData, resolveResult);
}

int Granite_Lookup_Dynamic_Anisotropic(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord, in bool asUDIM,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return asUDIM ? Granite_Lookup_UDIM_Anisotropic(grCB, translationTable, inputTexCoord,
            graniteLookupData, resolveResult) : Granite_Lookup_Anisotropic(grCB, translationTable,
            inputTexCoord, graniteLookupData, resolveResult);
}

int Granite_Lookup_Dynamic_Linear(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord, in bool asUDIM,
        in float LOD, out GraniteLODLookupData graniteLODLookupData, out gra_Float4 resolveResult) {
    return asUDIM ? Granite_Lookup_UDIM(grCB, translationTable, inputTexCoord, LOD,
            graniteLODLookupData, resolveResult) : Granite_Lookup(grCB, translationTable, inputTexCoord,
            LOD, graniteLODLookupData, resolveResult);
}

int Granite_Lookup_Dynamic_Linear(in GraniteConstantBuffers grCB,
        in GraniteTranslationTexture translationTable, in gra_Float2 inputTexCoord, in bool asUDIM,
        out GraniteLookupData graniteLookupData, out gra_Float4 resolveResult) {
    return asUDIM ? Granite_Lookup_UDIM_Linear(grCB, translationTable, inputTexCoord, graniteLookupData,
            resolveResult) : Granite_Lookup_Linear(grCB, translationTable, inputTexCoord,
            graniteLookupData, resolveResult);
}
#endif  // VARC_GRANITE_LOOKUPS_INCLUDED
