// SPDX-License-Identifier: Apache-2.0
// varc built-in, part of GraniteShaderLib3.cginc: the resolver passes, which write the tiles a pixel
// needs; without streaming a pixel needs none (see the fallback note at the top of
// GraniteShaderLib3.cginc). Written for varc.
#include "GraniteShaderLib3.cginc"
#ifndef VARC_GRANITE_RESOLVE_INCLUDED
#define VARC_GRANITE_RESOLVE_INCLUDED

gra_Float4 Granite_ResolverPixel(in GraniteConstantBuffers grCB, in gra_Float2 inputTexCoord,
        in float LOD) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, LOD);
}

gra_Float4 Granite_ResolverPixel_Anisotropic(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, 0);
}

gra_Float4 Granite_ResolverPixel_Anisotropic(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in gra_Float2 ddX, in gra_Float2 ddY) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, 0);
}

gra_Float4 Granite_ResolverPixel_Clamp(in GraniteConstantBuffers grCB, in gra_Float2 inputTexCoord,
        in float LOD) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, LOD);
}

gra_Float4 Granite_ResolverPixel_Clamp_Anisotropic(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, 0);
}

gra_Float4 Granite_ResolverPixel_Clamp_Anisotropic(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in gra_Float2 ddX, in gra_Float2 ddY) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, 0);
}

gra_Float4 Granite_ResolverPixel_Clamp_Linear(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, 0);
}

gra_Float4 Granite_ResolverPixel_Clamp_Linear(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in gra_Float2 ddX, in gra_Float2 ddY) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, 0);
}

gra_Float4 Granite_ResolverPixel_Linear(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, 0);
}

gra_Float4 Granite_ResolverPixel_Linear(in GraniteConstantBuffers grCB, in gra_Float2 inputTexCoord,
        in gra_Float2 ddX, in gra_Float2 ddY) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, 0);
}

gra_Float4 Granite_ResolverPixel_PreTransformed(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in float LOD) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, LOD);
}

gra_Float4 Granite_ResolverPixel_PreTransformed_Anisotropic(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, 0);
}

gra_Float4 Granite_ResolverPixel_PreTransformed_Anisotropic(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in gra_Float2 ddX, in gra_Float2 ddY) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, 0);
}

gra_Float4 Granite_ResolverPixel_PreTransformed_Clamp(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in float LOD) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, LOD);
}

gra_Float4 Granite_ResolverPixel_PreTransformed_Clamp_Anisotropic(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, 0);
}

gra_Float4 Granite_ResolverPixel_PreTransformed_Clamp_Anisotropic(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in gra_Float2 ddX, in gra_Float2 ddY) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, 0);
}

gra_Float4 Granite_ResolverPixel_PreTransformed_Clamp_Linear(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, 0);
}

gra_Float4 Granite_ResolverPixel_PreTransformed_Clamp_Linear(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in gra_Float2 ddX, in gra_Float2 ddY) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, 0);
}

gra_Float4 Granite_ResolverPixel_PreTransformed_Linear(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, 0);
}

gra_Float4 Granite_ResolverPixel_PreTransformed_Linear(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in gra_Float2 ddX, in gra_Float2 ddY) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, 0);
}

gra_Float4 Granite_ResolverPixel_PreTransformed_UDIM(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in float LOD) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, LOD);
}

gra_Float4 Granite_ResolverPixel_PreTransformed_UDIM_Anisotropic(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, 0);
}

gra_Float4 Granite_ResolverPixel_PreTransformed_UDIM_Anisotropic(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in gra_Float2 ddX, in gra_Float2 ddY) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, 0);
}

gra_Float4 Granite_ResolverPixel_PreTransformed_UDIM_Linear(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, 0);
}

gra_Float4 Granite_ResolverPixel_PreTransformed_UDIM_Linear(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in gra_Float2 ddX, in gra_Float2 ddY) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, 0);
}

gra_Float4 Granite_ResolverPixel_UDIM(in GraniteConstantBuffers grCB, in gra_Float2 inputTexCoord,
        in float LOD) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, LOD);
}

gra_Float4 Granite_ResolverPixel_UDIM_Anisotropic(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, 0);
}

gra_Float4 Granite_ResolverPixel_UDIM_Anisotropic(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in gra_Float2 ddX, in gra_Float2 ddY) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, 0);
}

gra_Float4 Granite_ResolverPixel_UDIM_Linear(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, 0);
}

gra_Float4 Granite_ResolverPixel_UDIM_Linear(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in gra_Float2 ddX, in gra_Float2 ddY) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, 0);
}

gra_Float4 Granite_ResolverPixel_Cube(in GraniteCubeConstantBuffers grCB,
        in gra_Float3 inputTexCoord, in float LOD) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord.xy, LOD);
}

gra_Float4 Granite_ResolverPixel_Cube_Anisotropic(in GraniteCubeConstantBuffers grCB,
        in gra_Float3 inputTexCoord) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord.xy, 0);
}

gra_Float4 Granite_ResolverPixel_Cube_Anisotropic(in GraniteCubeConstantBuffers grCB,
        in gra_Float3 inputTexCoord, in gra_Float3 ddX, in gra_Float3 ddY) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord.xy, 0);
}

gra_Float4 Granite_ResolverPixel_Cube_Clamp(in GraniteCubeConstantBuffers grCB,
        in gra_Float3 inputTexCoord, in float LOD) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord.xy, LOD);
}

gra_Float4 Granite_ResolverPixel_Cube_Clamp_Anisotropic(in GraniteCubeConstantBuffers grCB,
        in gra_Float3 inputTexCoord) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord.xy, 0);
}

gra_Float4 Granite_ResolverPixel_Cube_Clamp_Anisotropic(in GraniteCubeConstantBuffers grCB,
        in gra_Float3 inputTexCoord, in gra_Float3 ddX, in gra_Float3 ddY) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord.xy, 0);
}

gra_Float4 Granite_ResolverPixel_Cube_Clamp_Linear(in GraniteCubeConstantBuffers grCB,
        in gra_Float3 inputTexCoord) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord.xy, 0);
}

gra_Float4 Granite_ResolverPixel_Cube_Clamp_Linear(in GraniteCubeConstantBuffers grCB,
        in gra_Float3 inputTexCoord, in gra_Float3 ddX, in gra_Float3 ddY) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord.xy, 0);
}

gra_Float4 Granite_ResolverPixel_Cube_Linear(in GraniteCubeConstantBuffers grCB,
        in gra_Float3 inputTexCoord) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord.xy, 0);
}

gra_Float4 Granite_ResolverPixel_Cube_Linear(in GraniteCubeConstantBuffers grCB,
        in gra_Float3 inputTexCoord, in gra_Float3 ddX, in gra_Float3 ddY) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord.xy, 0);
}

gra_Float4 Granite_ResolverPixel_Cube_UDIM(in GraniteCubeConstantBuffers grCB,
        in gra_Float3 inputTexCoord, in float LOD) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord.xy, LOD);
}

gra_Float4 Granite_ResolverPixel_Cube_UDIM_Anisotropic(in GraniteCubeConstantBuffers grCB,
        in gra_Float3 inputTexCoord) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord.xy, 0);
}

gra_Float4 Granite_ResolverPixel_Cube_UDIM_Anisotropic(in GraniteCubeConstantBuffers grCB,
        in gra_Float3 inputTexCoord, in gra_Float3 ddX, in gra_Float3 ddY) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord.xy, 0);
}

gra_Float4 Granite_ResolverPixel_Cube_UDIM_Linear(in GraniteCubeConstantBuffers grCB,
        in gra_Float3 inputTexCoord) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord.xy, 0);
}

gra_Float4 Granite_ResolverPixel_Cube_UDIM_Linear(in GraniteCubeConstantBuffers grCB,
        in gra_Float3 inputTexCoord, in gra_Float3 ddX, in gra_Float3 ddY) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord.xy, 0);
}

gra_Float4 Granite_ResolverPixel_Dynamic_Anisotropic(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in bool asUDIM) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, 0);
}

gra_Float4 Granite_ResolverPixel_Dynamic_Linear(in GraniteConstantBuffers grCB,
        in gra_Float2 inputTexCoord, in bool asUDIM) {
    return GranitePrivate_ResolverPixel(grCB.tilesetBuffer, inputTexCoord, 0);
}
#endif  // VARC_GRANITE_RESOLVE_INCLUDED
