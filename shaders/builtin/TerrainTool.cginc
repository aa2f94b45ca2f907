// SPDX-License-Identifier: Apache-2.0
// varc built-in: TerrainTool.cginc. Coordinate helpers of terrain-painting tool shaders: from the
// paint context's uv (0..1 over the region being painted) to the brush's uv (an affine map set
// by the tool) and to the heightmap's uv. Written for varc from the documented behaviour of the
// TerrainTools PaintContext API; not derived from Unity.
#ifndef TERRAIN_TOOL_INCLUDED
#define TERRAIN_TOOL_INCLUDED

// brushUV = pcUV.x * _PCUVToBrushUVScales.xy + pcUV.y * _PCUVToBrushUVScales.zw + offset.
float4 _PCUVToBrushUVScales;
float2 _PCUVToBrushUVOffset;

float2 PaintContextUVToBrushUV(float2 pcUV) {
    return pcUV.x * _PCUVToBrushUVScales.xy + pcUV.y * _PCUVToBrushUVScales.zw + _PCUVToBrushUVOffset;
}

// The paint context's render texture is the heightmap region being painted: the same uv.
float2 PaintContextUVToHeightmapUV(float2 pcUV) {
    return pcUV;
}

#endif // TERRAIN_TOOL_INCLUDED
