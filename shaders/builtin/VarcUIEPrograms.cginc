// SPDX-License-Identifier: Apache-2.0
// varc built-in, part of UnityUIE.cginc: UI Toolkit's texture slots, coverage (clipping, rounded
// corners, signed-distance text) and its standard vertex and fragment programs. Written for varc.
#include "UnityUIE.cginc"
#ifndef VARC_UIE_PROGRAMS_INCLUDED
#define VARC_UIE_PROGRAMS_INCLUDED

// Slot |index| of the bound textures: _TextureInfo[index * UIE_TEXTURE_SLOT_SIZE] holds the
// texture's id (x) and texel size (zw).
TextureInfo GetTextureInfo(half index) {
    float4 data = _TextureInfo[(int)index * UIE_TEXTURE_SLOT_SIZE];
    TextureInfo info;
    info.textureId = data.x;
    info.unused = data.y;
    info.texelSize = data.zw;
    return info;
}

// The slot holding textureId (0 when none does).
half FindTextureSlot(float textureId) {
    for (int i = 0; i < UIE_TEXTURE_SLOT_COUNT; ++i) {
        if (fpEqual(_TextureInfo[i * UIE_TEXTURE_SLOT_SIZE].x, textureId))
            return (half)i;
    }
    return 0;
}

float4 SampleTextureSlot(half index, float2 uv) {
    int i = (int)index;
    float4 c = tex2D(_Texture0, uv);
    c = i == 1 ? tex2D(_Texture1, uv) : c;
    c = i == 2 ? tex2D(_Texture2, uv) : c;
    c = i == 3 ? tex2D(_Texture3, uv) : c;
#if UIE_TEXTURE_SLOT_COUNT == 8
    c = i == 4 ? tex2D(_Texture4, uv) : c;
    c = i == 5 ? tex2D(_Texture5, uv) : c;
    c = i == 6 ? tex2D(_Texture6, uv) : c;
    c = i == 7 ? tex2D(_Texture7, uv) : c;
#endif
    return c;
}

// The length of one pixel's step in uv.
float pixelDist(float2 uv) {
    return length(fwidth(uv));
}

// Coverage of a rounded corner: outer and inner are the pixel's position in the unit circle of
// the corner's outer and inner arc; inside the outer arc and outside the inner one, antialiased
// over a pixel.
float ComputeCoverage(float2 outer, float2 inner) {
    float outerCoverage = saturate(0.5 - (length(outer) - 1.0) / max(pixelDist(outer), 1e-5));
    float innerCoverage = saturate(0.5 + (length(inner) - 1.0) / max(pixelDist(inner), 1e-5));
    return outerCoverage * innerCoverage;
}

// Coverage of a signed-distance sample (0.5 on the edge), antialiased over a pixel.
float sdf(float distanceSample) {
    return saturate((distanceSample - 0.5) / max(fwidth(distanceSample), 1e-5) + 0.5);
}

// Coverage of signed-distance text: the distance sd (in texture units, 0 on the glyph's edge,
// positive inside) scaled by sdfScale, against the iso-perimeter offset (dilation), antialiased
// over the pixel's footprint in the font texture (uv / sdfSizeRCP texels).
float sd_to_coverage(float sd, float2 uv, float sdfSizeRCP, float sdfScale, float isoPerimeter) {
    float pixelInTexels = max(pixelDist(uv) / sdfSizeRCP, 1e-5);
    return saturate((sd * sdfScale + isoPerimeter) / pixelInTexels + 0.5);
}
float3 sd_to_coverage(float3 sd, float2 uv, float sdfSize, float sdfScale, float3 isoPerimeter, float3 softness) {
    float pixelInTexels = max(pixelDist(uv) * sdfSize, 1e-5);
    return saturate((sd * sdfScale + isoPerimeter) / (pixelInTexels + softness) + 0.5);
}

// A text fragment: vertexColor with the glyph's coverage (textAlpha is the distance sample,
// dilated by extraDilate) times opacity; dynamic-colour text keeps the vertex colour as it is.
UIE_FRAG_T uie_textcore(float textAlpha, float2 uv, float2 textCoreUV, float4 vertexColor, half opacity,
                        bool isDynamicColor, float extraDilate) {
    float coverage = sd_to_coverage(textAlpha - 0.5, textCoreUV, _FontTex_TexelSize.x, _FontTexSDFScale, extraDilate);
    float4 color = vertexColor;
    if (!isDynamicColor)
        color.rgb = saturate(color.rgb);
    return UIE_FRAG_T(color.rgb, color.a * coverage * opacity);
}

#include "VarcUIEVertex.cginc"

#endif  // VARC_UIE_PROGRAMS_INCLUDED
