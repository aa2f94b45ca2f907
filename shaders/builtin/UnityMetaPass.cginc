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
