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

#endif // UNITY_UI_INCLUDED
