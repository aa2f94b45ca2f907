// SPDX-License-Identifier: Apache-2.0
// varc built-in: TerrainPreview.cginc. Helpers of terrain-tool brush previews: a procedural grid
// of quads over the paint context (from SV_VertexID), affine maps from paint-context pixels to
// brush uv, heightmap uv and terrain object space (set by the tool), and an anti-aliased stripe.
// Written for varc from the documented behaviour of the TerrainTools PaintContext API; not
// derived from Unity.
#ifndef TERRAIN_PREVIEW_INCLUDED
#define TERRAIN_PREVIEW_INCLUDED

sampler2D _Heightmap;
// Grid of the preview mesh: x, y = quads per row and per column.
float4 _QuadRez;
// Each map is value = p.x * PCPixelsX + p.y * PCPixelsY + Offset (p in paint-context pixels);
// the object position also adds heightmapSample * _ObjectPos_HeightMapSample.
float2 _BrushUV_PCPixelsX, _BrushUV_PCPixelsY, _BrushUV_Offset;
float2 _HeightmapUV_PCPixelsX, _HeightmapUV_PCPixelsY, _HeightmapUV_Offset;
float3 _ObjectPos_PCPixelsX, _ObjectPos_PCPixelsY, _ObjectPos_HeightMapSample, _ObjectPos_Offset;
float3 _TerrainObjectToWorldOffset;

// Vertex vertexID of the grid: quad vertexID / 6 (row-major, _QuadRez.x per row), corner
// vertexID % 6 of its two triangles; the result is in paint-context pixels.
float2 BuildProceduralQuadMeshVertex(uint vertexID) {
    static const float2 corners[6] = {
        float2(0, 0), float2(1, 0), float2(1, 1), float2(0, 0), float2(1, 1), float2(0, 1)};
    uint quad = vertexID / 6u;
    uint perRow = max((uint)_QuadRez.x, 1u);
    float2 cell = float2(quad % perRow, quad / perRow);
    return cell + corners[vertexID % 6u];
}

float2 PaintContextPixelsToBrushUV(float2 pcPixels) {
    return pcPixels.x * _BrushUV_PCPixelsX + pcPixels.y * _BrushUV_PCPixelsY + _BrushUV_Offset;
}
float2 PaintContextPixelsToHeightmapUV(float2 pcPixels) {
    return pcPixels.x * _HeightmapUV_PCPixelsX + pcPixels.y * _HeightmapUV_PCPixelsY + _HeightmapUV_Offset;
}
float3 PaintContextPixelsToObjectPosition(float2 pcPixels, float heightmapSample) {
    return pcPixels.x * _ObjectPos_PCPixelsX + pcPixels.y * _ObjectPos_PCPixelsY +
           heightmapSample * _ObjectPos_HeightMapSample + _ObjectPos_Offset;
}
float3 TerrainObjectToWorldPosition(float3 objectPosition) {
    return objectPosition + _TerrainObjectToWorldOffset;
}

// 1 on the line x = stripeX, falling linearly to 0 at pixelWidth from it.
float Stripe(in float x, in float stripeX, in float pixelWidth) {
    return saturate(1.0 - abs(x - stripeX) / max(pixelWidth, 1e-6));
}

#endif // TERRAIN_PREVIEW_INCLUDED
