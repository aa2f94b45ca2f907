// SPDX-License-Identifier: Apache-2.0
// varc built-in, part of UnityUIE.cginc: UI Toolkit's per-element data loads and its standard
// vertex and fragment programs. Written for varc; the data layouts are described in
// UnityUIE.cginc.
#include "UnityUIE.cginc"
#ifndef VARC_UIE_VERTEX_INCLUDED
#define VARC_UIE_VERTEX_INCLUDED

// The element's transform, entry ids.x of the transform page (three rows of a 3x4 matrix).
void uie_vert_load_payload(appdata_t v) {
    float id = floor(v.ids.x * 255.0 + 0.5);
#if UIE_SHADER_INFO_IN_VS
    float2 texel = uie_decode_shader_info_texel_pos(v.xformClipPages.xy, id, 3.0);
    float4 row0 = SampleShaderInfo(texel), row1 = SampleShaderInfo(texel + float2(0, 1));
    float4 row2 = SampleShaderInfo(texel + float2(0, 2));
#else
    int i = (int)id * 3;
    float4 row0 = _Transforms[i], row1 = _Transforms[i + 1], row2 = _Transforms[i + 2];
#endif
    uie_toWorldMat = float4x4(row0, row1, row2, float4(0, 0, 0, 1));
}

// The vertex colour (converted to linear in a linear-space project) and the shader-info texels
// of the element's clip rect, opacity and colour; the opacity itself.
void uie_std_vert_shader_info(appdata_t v, out UIE_V2F_COLOR_T color, out float2 clipRectUV, out float2 opacityUV,
                              out float opacity, out float2 colorUV) {
    color = v.color;
#if !UIE_COLORSPACE_GAMMA
    color.rgb = uie_gamma_to_linear(v.color.rgb);
#endif
    float4 ids = floor(v.ids * 255.0 + 0.5);
    clipRectUV = uie_decode_shader_info_texel_pos(v.xformClipPages.zw, ids.y, 1.0);
    opacityUV = uie_decode_shader_info_texel_pos(v.opacityColorPages.xy, ids.z, 1.0);
    colorUV = uie_decode_shader_info_texel_pos(v.opacityColorPages.zw, ids.w, 1.0);
#if UIE_SHADER_INFO_IN_VS
    opacity = SampleShaderInfo(opacityUV).a;
#else
    opacity = 1.0;
#endif
}
// 2019.4 / 2020.3: the colour, with the clip rect (xMin, yMin, xMax, yMax) returned.
float4 uie_std_vert_shader_info(appdata_t v, out UIE_V2F_COLOR_T color) {
    float2 clipRectUV, opacityUV, colorUV;
    float opacity;
    uie_std_vert_shader_info(v, color, clipRectUV, opacityUV, opacity, colorUV);
    color.a *= opacity;
#if UIE_SHADER_INFO_IN_VS
    return SampleShaderInfo(clipRectUV);
#else
    return _ClipRects[(int)floor(v.ids.y * 255.0 + 0.5)];
#endif
}

// 2019.4 / 2020.3: the displacement that moves an edge vertex outwards for antialiasing, at least
// minDisplacement on each axis unless that axis may not shrink.
float2 uie_get_border_offset(float4 vertex, float2 embeddedDisplacement, float minDisplacement, bool noShrinkX,
                             bool noShrinkY) {
    float2 d = embeddedDisplacement;
    float2 grown = sign(d) * max(abs(d), minDisplacement);
    return float2(noShrinkX ? d.x : grown.x, noShrinkY ? d.y : grown.y);
}

v2f uie_std_vert(appdata_t v, out float4 clipSpacePos) {
    v2f OUT;
    UNITY_SETUP_INSTANCE_ID(v);
    UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(OUT);
    uie_vert_load_payload(v);
    float3 world = mul(uie_toWorldMat, float4(v.vertex.xyz, 1)).xyz;
    OUT.pos = UnityObjectToClipPos(float4(world, 1));
    clipSpacePos = OUT.pos;
    float2 clipRectUV, opacityUV, colorUV;
    float opacity;
    uie_std_vert_shader_info(v, OUT.color, clipRectUV, opacityUV, opacity, colorUV);
    OUT.color.a *= opacity;
    OUT.uvClip = float4(v.uv, world.xy);
    float4 flags = floor(v.flags * 255.0 + 0.5);
    OUT.typeTexSettings = half4(flags.x, FindTextureSlot(v.textureId), flags.y + flags.z * 256.0, 0);
    OUT.clipRectOpacityUVs = fixed4(clipRectUV, opacityUV);
    OUT.colorUVs = colorUV;
    OUT.circle = v.circle;
    return OUT;
}
v2f uie_std_vert(appdata_t v) {
    float4 clipSpacePos;
    return uie_std_vert(v, clipSpacePos);
}

// 1 inside the element's clip rect (the shader-info texel: xMin, yMin, xMax, yMax), 0 outside.
float uie_fragment_clip(v2f IN) {
    float4 rect = SampleShaderInfo(IN.clipRectOpacityUVs.xy);
    float2 inside = step(rect.xy, IN.uvClip.zw) * step(IN.uvClip.zw, rect.zw);
    return inside.x * inside.y;
}

// Render types (typeTexSettings.x): 0 solid colour, 1 textured, 2 text (_FontTex's distance
// field), 3 SVG gradient; rounded corners (circle) and the clip rect cut coverage.
UIE_FRAG_T uie_std_frag(v2f IN) {
    float2 uv = IN.uvClip.xy;
    half type = IN.typeTexSettings.x, slot = IN.typeTexSettings.y;
    GradientLocation g = uie_sample_gradient_location(IN.typeTexSettings.z, uv, _GradientSettingsTex,
                                                      _GradientSettingsTex_TexelSize.xy);
    float4 textured = SampleTextureSlot(slot, type == 3 ? g.uv : uv) * IN.color;
    float4 text = uie_textcore(tex2D(_FontTex, uv).a, uv, uv, IN.color, 1, false, 0);
    float4 color = type == 2 ? text : (type == 0 ? (float4)IN.color : textured);
    float corner = ComputeCoverage(IN.circle.xy, IN.circle.zw);
    color.a *= uie_fragment_clip(IN) * (any(IN.circle != 0) ? corner : 1.0);
    return (UIE_FRAG_T)color;
}

#ifndef UIE_CUSTOM_SHADER
v2f vert(appdata_t v) {
    return uie_std_vert(v);
}
UIE_FRAG_T frag(v2f IN) : SV_Target {
    return uie_std_frag(IN);
}
#endif

#endif  // VARC_UIE_VERTEX_INCLUDED
