// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityUI.cginc. Helpers of Unity's UI (uGUI) shaders: rectangular clipping of
// canvas elements (RectMask2D). _ClipRect and _TextureSampleAdd are material values the UI
// shader declares itself. Written for varc from the documented behaviour.
#ifndef UNITY_UI_INCLUDED
#define UNITY_UI_INCLUDED

// 1 inside the axis-aligned rectangle clipRect = (xMin, yMin, xMax, yMax), edges included,
// 0 outside. position and clipRect are in the canvas's (object/world) space.
inline float UnityGet2DClipping(in float2 position, in float4 clipRect) {
    float2 inside = step(clipRect.xy, position.xy) * step(position.xy, clipRect.zw);
    return inside.x * inside.y;
}

// sRGB-encoded (gamma) colour to linear, per channel (IEC 61966-2-1): UI shaders convert vertex
// colours authored in gamma space when the project renders in linear space.
inline half3 UIGammaToLinear(half3 value) {
    half3 low = value / 12.92;
    half3 high = pow((value + 0.055) / 1.055, 2.4);
    return half3(value.r <= 0.04045 ? low.r : high.r, value.g <= 0.04045 ? low.g : high.g,
                 value.b <= 0.04045 ? low.b : high.b);
}

// Colour of a UI texture split in two (ETC1: rgb in mainTexture, alpha in alphaTexture.r), plus
// the canvas's _TextureSampleAdd.
inline fixed4 UnityGetUIDiffuseColor(in float2 position, in sampler2D mainTexture, in sampler2D alphaTexture, fixed4 textureSampleAdd) {
    return fixed4(tex2D(mainTexture, position).rgb + textureSampleAdd.rgb,
                  tex2D(alphaTexture, position).r + textureSampleAdd.a);
}

#endif // UNITY_UI_INCLUDED
