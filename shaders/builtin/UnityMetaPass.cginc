// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityMetaPass.cginc. The "Meta" pass a lightmap baker renders to read a
// surface's albedo and emission in lightmap space: the vertex position is the lightmap uv, and
// the fragment writes the albedo or the emission as the baker asks. Controls and editor
// visualisation values: docs/SHADER_ABI.md §4.13. Written for varc from the documented behaviour.
#ifndef UNITY_META_PASS_INCLUDED
#define UNITY_META_PASS_INCLUDED

#include "UnityCG.cginc"

CBUFFER_START(UnityMetaPass)
    // x: place vertices at the baked lightmap uv (uv1); y: at the realtime lightmap uv (uv2).
    bool4 unity_MetaVertexControl;
    // x: output albedo; y: output emission.
    bool4 unity_MetaFragmentControl;
    float unity_OneOverOutputBoost;   // albedo is raised to saturate(this) (1 = unchanged)
    float unity_MaxOutputValue;       // albedo upper clamp
    float unity_UseLinearSpace;       // 1: emission stays linear (always so in varc)
CBUFFER_END

// Editor visualisation modes (EDITOR_VISUALIZATION; the values a runtime never needs to set).
#define EDITORVIZ_PBR_VALIDATION_ALBEDO 0
#define EDITORVIZ_PBR_VALIDATION_METALSPECULAR 1
#define EDITORVIZ_TEXTURE 2
#define EDITORVIZ_SHOWLIGHTMASK 3
CBUFFER_START(UnityEditorVisualization)
    int unity_VisualizationMode;
    int unity_EditorViz_UVIndex;
    float4 unity_EditorViz_Texture_ST;
    float4 unity_EditorViz_Decode_HDR;
    float4 unity_EditorViz_ColorMul;
    float4 unity_EditorViz_ColorAdd;
    float4 unity_EditorViz_Color;
    float4 unity_EditorViz_ChannelSelect;
    float4x4 unity_EditorViz_WorldToLight;
    float4 unity_EditorViz_LightType;
CBUFFER_END
sampler2D unity_EditorViz_Texture;
sampler2D unity_EditorViz_LightTexture;
sampler2D unity_EditorViz_LightTextureB;

// PBR validation (the editor's "Validate Albedo" / "Validate Metal/Specular" scene views): the
// modes, the thresholds the editor sets, and the colours marking values out of range.
#define PBR_VALIDATION_ALBEDO EDITORVIZ_PBR_VALIDATION_ALBEDO
#define PBR_VALIDATION_METALSPECULAR EDITORVIZ_PBR_VALIDATION_METALSPECULAR
half4 unity_MaterialValidateLowColor;       // values below the valid range
half4 unity_MaterialValidateHighColor;      // values above it
half4 unity_MaterialValidatePureMetalColor; // metals whose albedo is not black
bool unity_EditorViz_ConvertToLinearSpace;  // 1: the visualised texture holds sRGB colours
half unity_EditorViz_Exposure;              // exposure (stops) applied to HDR visualisations
int _CheckPureMetal;
int _CheckAlbedo;
half4 _AlbedoCompareColor;                  // rgb: the reference colour of the albedo check
half _AlbedoMinLuminance;
half _AlbedoMaxLuminance;
half _AlbedoHueTolerance;
half _AlbedoSaturationTolerance;
// Physically plausible ranges (linear): specular reflectance of dielectrics, gems and metals,
// and diffuse albedo (from charcoal to fresh snow).
static const float dieletricMin = 0.02;
static const float dieletricMax = 0.07;
static const float gemsMin = 0.07;
static const float gemsMax = 0.22;
static const float conductorMin = 0.45;
static const float conductorMax = 1.00;
static const float albedoMin = 0.012;
static const float albedoMax = 0.9;

// uv of the visualised texture: uv0, uv1 or uv2 (uvIndex 0, 1, 2) with its scale/offset.
float2 UnityMetaVizUV(int uvIndex, float2 uv0, float2 uv1, float2 uv2, float4 st) {
    float2 uv = (uvIndex == 0) ? uv0 : ((uvIndex == 1) ? uv1 : uv2);
    return uv * st.xy + st.zw;
}

struct UnityMetaInput {
    half3 Albedo;
    half3 Emission;
    half3 SpecularColor;
#ifdef EDITOR_VISUALIZATION
    float2 VizUV;
    float4 LightCoord;
#endif
};

// Hue, saturation, value of a colour whose largest component is dominantColor, the hue sector
// starting at offset (0 red, 2 green, 4 blue) and colorone - colortwo the signed distance
// within it: H = frac((offset + (colorone - colortwo) / chroma) / 6), S = chroma / V, V = max.
// A grey (chroma 0) has H = S = 0.
half3 UnityMeta_RGBToHSVHelper(float offset, half dominantColor, half colorone, half colortwo) {
    half chroma = dominantColor - min(colorone, colortwo);
    half h = chroma > 0 ? frac((offset + (colorone - colortwo) / chroma) / 6.0) : 0;
    half s = dominantColor > 0 ? chroma / dominantColor : 0;
    return half3(h, s, dominantColor);
}
// The usual hexcone HSV of an RGB colour (H, S, V in [0, 1]).
half3 UnityMeta_RGBToHSV(half3 rgbColor) {
    if (rgbColor.r >= rgbColor.g && rgbColor.r >= rgbColor.b)
        return UnityMeta_RGBToHSVHelper(0, rgbColor.r, rgbColor.g, rgbColor.b);
    if (rgbColor.g >= rgbColor.b)
        return UnityMeta_RGBToHSVHelper(2, rgbColor.g, rgbColor.b, rgbColor.r);
    return UnityMeta_RGBToHSVHelper(4, rgbColor.b, rgbColor.r, rgbColor.g);
}

// Albedo validation: the low / high colour when the albedo's luminance is outside
// [_AlbedoMinLuminance, _AlbedoMaxLuminance], or (with _CheckAlbedo) when its hue or saturation
// differs from _AlbedoCompareColor's by more than the tolerances; else the albedo's luminance
// as a grey with alpha 0 (nothing to flag).
half4 UnityMeta_pbrAlbedo(UnityMetaInput IN) {
    half lum = Luminance(IN.Albedo);
    if (lum < _AlbedoMinLuminance)
        return unity_MaterialValidateLowColor;
    if (lum > _AlbedoMaxLuminance)
        return unity_MaterialValidateHighColor;
    if (_CheckAlbedo != 0) {
        half3 hsv = UnityMeta_RGBToHSV(IN.Albedo);
        half3 ref = UnityMeta_RGBToHSV(_AlbedoCompareColor.rgb);
        half dh = abs(hsv.x - ref.x);
        dh = min(dh, 1 - dh);  // hue is circular
        if (dh > _AlbedoHueTolerance || hsv.y < ref.y - _AlbedoSaturationTolerance)
            return unity_MaterialValidateLowColor;
        if (hsv.y > ref.y + _AlbedoSaturationTolerance)
            return unity_MaterialValidateHighColor;
    }
    return half4(lum, lum, lum, 0);
}
// Metal/specular validation: a metal (specular luminance >= conductorMin) with a non-black
// albedo is flagged with the pure-metal colour when _CheckPureMetal is on; specular luminance
// below the dielectric range or between the gem and metal ranges is low, above the metal range
// high; else the specular luminance as a grey with alpha 0.
half4 UnityMeta_pbrMetalspec(UnityMetaInput IN) {
    half lum = Luminance(IN.SpecularColor);
    if (lum >= conductorMin && _CheckPureMetal != 0 && Luminance(IN.Albedo) > 0)
        return unity_MaterialValidatePureMetalColor;
    if (lum < dieletricMin || (lum > gemsMax && lum < conductorMin))
        return unity_MaterialValidateLowColor;
    if (lum > conductorMax)
        return unity_MaterialValidateHighColor;
    return half4(lum, lum, lum, 0);
}

// Clip position of a vertex in lightmap space: xy = lightmap uv (scaled/offset), z a tiny
// non-zero depth so that the vertex is not clipped; then UNITY_MATRIX_VP, which the baker sets
// to map uv [0,1]^2 onto the target.
float4 UnityMetaVertexPosition(float4 vertex, float2 uv1, float2 uv2, float4 lightmapST, float4 dynlightmapST) {
    if (unity_MetaVertexControl.x) {
        vertex.xy = uv1 * lightmapST.xy + lightmapST.zw;
        vertex.z = vertex.z > 0 ? 1.0e-4f : 0.0f;
    }
    if (unity_MetaVertexControl.y) {
        vertex.xy = uv2 * dynlightmapST.xy + dynlightmapST.zw;
        vertex.z = vertex.z > 0 ? 1.0e-4f : 0.0f;
    }
    return mul(UNITY_MATRIX_VP, float4(vertex.xyz, 1.0));
}

// Albedo request: (clamp(albedo^saturate(unity_OneOverOutputBoost), 0, unity_MaxOutputValue), 1).
// Emission request: (emission, 1). Nothing requested: 0.
half4 UnityMetaFragment(UnityMetaInput IN) {
    half4 res = 0;
    if (unity_MetaFragmentControl.x) {
        res = half4(IN.Albedo, 1);
        res.rgb = clamp(pow(res.rgb, saturate(unity_OneOverOutputBoost)), 0, unity_MaxOutputValue);
    }
    if (unity_MetaFragmentControl.y) {
        res = half4(IN.Emission, 1.0);
    }
    return res;
}

#endif // UNITY_META_PASS_INCLUDED
