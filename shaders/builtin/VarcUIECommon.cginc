// SPDX-License-Identifier: Apache-2.0
// varc built-in, part of UnityUIE.cginc: UI Toolkit's helper functions and its standard vertex and
// fragment programs. Written for varc; the data layouts are described in UnityUIE.cginc.
#include "UnityUIE.cginc"
#ifndef VARC_UIE_COMMON_INCLUDED
#define VARC_UIE_COMMON_INCLUDED

// sRGB transfer curves (IEC 61966-2-1), per channel.
half3 uie_gamma_to_linear(half3 value) {
    return value <= 0.04045 ? value / 12.92 : pow((value + 0.055) / 1.055, 2.4);
}
half3 uie_linear_to_gamma(half3 value) {
    return value <= 0.0031308 ? value * 12.92 : 1.055 * pow(max(value, 0), 1.0 / 2.4) - 0.055;
}

// Two 16-bit integers from four 8-bit channels, low byte first: (r + 256 g, b + 256 a).
float2 uie_unpack_float2(fixed4 c) {
    float4 b = floor(c * 255.0 + 0.5);
    return float2(b.r + b.g * 256.0, b.b + b.a * 256.0);
}

// The texel of entry |id| of the page at pageXY of the shader-info texture: pages are 32 texels
// wide; an entry spans |yStride| rows.
float2 uie_decode_shader_info_texel_pos(float2 pageXY, float id, float yStride) {
    const float kPageWidth = 32.0;
    float column = fmod(id, kPageWidth), row = floor(id / kPageWidth);
    return float2(pageXY.x * kPageWidth + column, pageXY.y * kPageWidth * yStride + row * yStride);
}

// The shader-info texel at texel coordinates uv (texel centres).
float4 SampleShaderInfo(half2 uv) {
    return tex2Dlod(_ShaderInfoTex, float4((uv + 0.5) * _ShaderInfoTex_TexelSize.xy, 0, 0));
}

bool fpEqual(float a, float b) {
    return abs(a - b) < 1e-4;
}

// Bit |value| (a power of two) of a float bit set: whether it is set; clears it from flags, so
// that testing from the largest bit down decodes the set.
float TestForValue(float value, inout float flags) {
    if (flags >= value) {
        flags -= value;
        return 1.0;
    }
    return 0.0;
}

// The position of pos relative to the rectangle from a to b: 0 at a, 1 at b.
float2 ComputeRelativeClipRectCoords(float2 a, float2 b, float2 pos) {
    return (pos - a) / (b - a);
}

// Clip-space xy snapped to the nearest pixel corner of the viewport.
float2 uie_snap_to_integer_pos(float2 clipSpaceXY) {
    return floor(clipSpaceXY * _ClipSpaceParams.xy + 0.5) * _ClipSpaceParams.zw;
}

// The first point where the ray from rayStart (inside the unit circle) along rayDir leaves it:
// the positive root t of |rayStart + t rayDir| = 1.
float2 uie_ray_unit_circle_first_hit(float2 rayStart, float2 rayDir) {
    float a = dot(rayDir, rayDir), b = 2.0 * dot(rayStart, rayDir), c = dot(rayStart, rayStart) - 1.0;
    float t = (-b + sqrt(max(b * b - 4.0 * a * c, 0.0))) / (2.0 * a);
    return rayStart + t * rayDir;
}

// A radial gradient's parameter at uv (the unit circle's coordinates): the distance from the
// focus over the distance from the focus to the circle along the same ray.
float uie_radial_address(float2 uv, float2 focus) {
    float2 dir = uv - focus;
    float len = length(dir);
    if (len < 1e-5)
        return 0.0;
    float2 hit = uie_ray_unit_circle_first_hit(focus, dir / len);
    return len / max(length(hit - focus), 1e-5);
}

// A gradient of the settings texture, row settingIndex: texel 0 holds the type (r > 0.5: radial),
// the address mode (g * 255: 0 clamp, 1 repeat, 2 mirror) and the radial focus (ba * 2 - 1);
// texels 1 and 2 the atlas position and size of the colour ramp (uie_unpack_float2).
GradientLocation uie_sample_gradient_location(float settingIndex, float2 uv, sampler2D settingsTex, float2 texelSize) {
    float y = (settingIndex + 0.5) * texelSize.y;
    float4 settings = tex2Dlod(settingsTex, float4(0.5 * texelSize.x, y, 0, 0));
    float2 pos = uie_unpack_float2(tex2Dlod(settingsTex, float4(1.5 * texelSize.x, y, 0, 0)));
    float2 size = uie_unpack_float2(tex2Dlod(settingsTex, float4(2.5 * texelSize.x, y, 0, 0)));
    float t = settings.r > 0.5 ? uie_radial_address(uv * 2.0 - 1.0, settings.ba * 2.0 - 1.0) : uv.x;
    float mode = floor(settings.g * 255.0 + 0.5);
    t = mode == 1 ? frac(t) : (mode == 2 ? 1.0 - abs(frac(t * 0.5) * 2.0 - 1.0) : saturate(t));
    GradientLocation g;
    g.location = float4(pos, size);
    g.uv = (pos + float2(t * (size.x - 1.0) + 0.5, size.y * 0.5)) * texelSize;
    return g;
}

#include "VarcUIEPrograms.cginc"

#endif  // VARC_UIE_COMMON_INCLUDED
