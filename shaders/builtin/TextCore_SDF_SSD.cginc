// SPDX-License-Identifier: Apache-2.0
// varc built-in: TextCore_SDF_SSD.cginc. Vertex and pixel programs of a signed-distance-field text
// shader whose anti-aliasing width comes from screen-space derivatives ("SSD") of the atlas
// coordinate, so no per-vertex scale is needed. Keywords: OUTLINE_ON, UNDERLAY_ON or
// UNDERLAY_INNER, GLOW_ON, UNITY_UI_CLIP_RECT, UNITY_UI_ALPHACLIP. Output colours are
// premultiplied by alpha (blend One OneMinusSrcAlpha). Written for varc from the SDF technique
// (Green 2007) and the TextCore property names; not derived from Unity's file.
//
// SDF contract: the atlas alpha a is 0.5 on the glyph edge and changes by 0.5 over
// _GradientScale texels (a > 0.5 inside). With t = texels per screen pixel (|fwidth(uv * size)|
// / sqrt 2), one unit of a spans scale = 2 _GradientScale / t screen pixels, and the signed
// distance of a pixel to the dilated edge is sd = (a - 0.5 + weight) * scale pixels, where
// weight = ((bold ? _WeightBold : _WeightNormal) / 4 + _FaceDilate) * _ScaleRatioA / 2.
#ifndef VARC_TEXTCORE_SDF_SSD_INCLUDED
#define VARC_TEXTCORE_SDF_SSD_INCLUDED

#include "UnityCG.cginc"
#include "UnityUI.cginc"
#include "TextCoreProperties.cginc"

float4 _MainTex_TexelSize;          // (1/width, 1/height, width, height) of the SDF atlas
sampler2D _GUIClipTexture;          // editor GUI clipping mask (alpha); white when not bound
float4x4 unity_GUIClipTextureMatrix; // world -> _GUIClipTexture uv

struct vertex_t {
    float4 position : POSITION;
    float3 normal : NORMAL;
    float4 color : COLOR;           // sRGB vertex colour
    float4 texcoord0 : TEXCOORD0;   // xy: atlas uv
    float2 texcoord1 : TEXCOORD1;   // y: glyph scale, negative for bold glyphs
};

struct pixel_t {
    float4 position : SV_POSITION;
    float4 faceColor : COLOR;       // premultiplied
    float4 outlineColor : COLOR1;   // premultiplied
    float2 texcoord0 : TEXCOORD0;   // atlas uv
    float4 param : TEXCOORD1;       // (weight, outline width, outline softness, bold) in units of a
    float2 clipUV : TEXCOORD2;      // _GUIClipTexture uv
#if defined(UNDERLAY_ON) || defined(UNDERLAY_INNER)
    float4 underlayColor : COLOR2;  // premultiplied
    float4 texcoord2 : TEXCOORD3;   // (underlay atlas uv, underlay edge in a, softness in a)
#endif
#if defined(UNITY_UI_CLIP_RECT)
    float2 clipPosition : TEXCOORD4; // object-space position, tested against _ClipRect
#endif
};

// sRGB-encoded colour to linear (IEC 61966-2-1) per rgb channel; alpha unchanged.
float4 SRGBToLinear(float4 rgba) {
    float3 c = rgba.rgb;
    float3 low = c / 12.92;
    float3 high = pow((c + 0.055) / 1.055, 2.4);
    return float4(c.r <= 0.04045 ? low.r : high.r, c.g <= 0.04045 ? low.g : high.g,
                  c.b <= 0.04045 ? low.b : high.b, rgba.a);
}

// Vertex colours are authored in sRGB: linearised unless the project renders in gamma space.
float4 VarcTextCoreVertexColor(float4 color) {
#if defined(UNITY_COLORSPACE_GAMMA)
    return color;
#else
    return SRGBToLinear(color);
#endif
}

pixel_t VertShader(vertex_t input) {
    pixel_t output;
    UNITY_INITIALIZE_OUTPUT(pixel_t, output);
    float4 vert = input.position;
    vert.xy += float2(_VertexOffsetX, _VertexOffsetY);
    output.position = UnityObjectToClipPos(vert.xyz);

    float bold = step(input.texcoord1.y, 0);
    float weight = (lerp(_WeightNormal, _WeightBold, bold) / 4.0 + _FaceDilate) * _ScaleRatioA * 0.5;
    output.param = float4(weight, _OutlineWidth * _ScaleRatioA * 0.5, _OutlineSoftness * _ScaleRatioA * 0.5, bold);

    float4 color = VarcTextCoreVertexColor(input.color);
    float4 face = color * _FaceColor;
    float4 outline = float4(_OutlineColor.rgb, _OutlineColor.a * color.a);
    output.faceColor = float4(face.rgb * face.a, face.a);
    output.outlineColor = float4(outline.rgb * outline.a, outline.a);
    output.texcoord0 = input.texcoord0.xy;
    output.clipUV = mul(unity_GUIClipTextureMatrix, mul(unity_ObjectToWorld, float4(vert.xyz, 1))).xy;

#if defined(UNDERLAY_ON) || defined(UNDERLAY_INNER)
    // The offset is in SDF units of the underlay ratio, converted to atlas uv.
    float2 offset = -float2(_UnderlayOffsetX, _UnderlayOffsetY) * _ScaleRatioC * _GradientScale * _MainTex_TexelSize.xy;
    float edge = 0.5 - (_UnderlayDilate * _ScaleRatioC * 0.5 + weight);
    float4 underlay = float4(_UnderlayColor.rgb, _UnderlayColor.a * color.a);
    output.underlayColor = float4(underlay.rgb * underlay.a, underlay.a);
    output.texcoord2 = float4(input.texcoord0.xy + offset, edge, _UnderlaySoftness * _ScaleRatioC * 0.5);
#endif
#if defined(UNITY_UI_CLIP_RECT)
    output.clipPosition = vert.xy;
#endif
    return output;
}

// Screen pixels per unit of SDF alpha at this pixel (see the contract above).
float VarcTextCoreSdfScale(float2 uv) {
    float texelsPerPixel = length(fwidth(uv * _MainTex_TexelSize.zw)) * 0.70710678;
    return 2.0 * _GradientScale * (_Sharpness + 1.0) / max(texelsPerPixel, 1e-5);
}

// Soft rectangle mask: 1 inside _ClipRect, falling linearly over _MaskSoftnessX/Y centred on
// its edges; a hard edge (UnityGet2DClipping) when the softness is 0.
float VarcTextCoreClipRect(float2 position) {
    float2 softness = float2(_MaskSoftnessX, _MaskSoftnessY);
    if (softness.x <= 0 && softness.y <= 0) return UnityGet2DClipping(position, _ClipRect);
    float2 inside = min(position - _ClipRect.xy, _ClipRect.zw - position);
    float2 m = saturate(inside / max(softness, 1e-4) + 0.5);
    return m.x * m.y;
}

float4 PixShader(pixel_t input) : SV_Target {
    float a = tex2D(_MainTex, input.texcoord0).a;
    float scale = VarcTextCoreSdfScale(input.texcoord0);
    float sd = (a - 0.5 + input.param.x) * scale;

#if defined(OUTLINE_ON)
    // The outline straddles the dilated edge; its softness widens the outer ramp.
    float width = input.param.y * scale;
    float softness = input.param.z * scale;
    float faceMix = saturate(sd - width * 0.5 + 0.5);
    float coverage = saturate((sd + width * 0.5) / (1.0 + softness) + 0.5);
    float4 c = lerp(input.outlineColor, input.faceColor, faceMix) * coverage;
#else
    float4 c = input.faceColor * saturate(sd + 0.5);
#endif

#if defined(UNDERLAY_ON) || defined(UNDERLAY_INNER)
    float u = tex2D(_MainTex, input.texcoord2.xy).a;
    float uSoft = 1.0 + input.texcoord2.w * scale;
    #if defined(UNDERLAY_ON)
    float uAlpha = saturate((u - input.texcoord2.z) * scale / uSoft + 0.5);
    #else
    float uAlpha = saturate((input.texcoord2.z - u) * scale / uSoft + 0.5) * saturate(sd + 0.5);
    #endif
    c += input.underlayColor * uAlpha * (1.0 - c.a);
#endif

#if defined(GLOW_ON)
    // Glow around the offset edge: falls from 1 to 0 over _GlowOuter outside and _GlowInner
    // inside (units of a scaled by _ScaleRatioB), shaped by _GlowPower; added to the colour.
    float g = a - 0.5 + input.param.x - _GlowOffset * _ScaleRatioB * 0.5;
    float reach = (g < 0 ? _GlowOuter : _GlowInner) * _ScaleRatioB * 0.5;
    float glow = pow(saturate(1.0 - abs(g) / max(reach, 1e-4)), 1.0 / max(_GlowPower, 1e-3));
    float glowAlpha = saturate(_GlowColor.a * glow * input.faceColor.a);
    c.rgb += _GlowColor.rgb * glowAlpha;
    c.a = saturate(c.a + glowAlpha * (1.0 - c.a));
#endif

#if defined(UNITY_UI_CLIP_RECT)
    c *= VarcTextCoreClipRect(input.clipPosition);
#endif
    c *= tex2D(_GUIClipTexture, input.clipUV).a;
#if defined(UNITY_UI_ALPHACLIP)
    clip(c.a - 0.001);
#endif
    return c;
}

#endif // VARC_TEXTCORE_SDF_SSD_INCLUDED
