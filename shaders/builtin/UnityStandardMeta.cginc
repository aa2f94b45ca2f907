// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityStandardMeta.cginc. The Meta pass of the Standard shader (vert_meta /
// frag_meta): albedo for the lightmapper, brightened by the specular colour of rough surfaces,
// and the emission. Written for varc from the documented behaviour.
#ifndef UNITY_STANDARD_META_INCLUDED
#define UNITY_STANDARD_META_INCLUDED

// The meta pass's vertex input carries the realtime lightmap uv (VertexInput.uv2); the compile
// driver defines this for LightMode Meta passes, Unity 5.6-2017.4's file defined it itself.
#ifndef UNITY_PASS_META
#define UNITY_PASS_META 1
#endif
#include "UnityCG.cginc"
#include "UnityStandardInput.cginc"
#include "UnityMetaPass.cginc"
#include "UnityStandardCore.cginc"

struct v2f_meta {
    float4 pos : SV_POSITION;
    float4 uv : TEXCOORD0;
#ifdef EDITOR_VISUALIZATION
    float2 vizUV : TEXCOORD1;
    float4 lightCoord : TEXCOORD2;
#endif
};

v2f_meta vert_meta(VertexInput v) {
    v2f_meta o;
    UNITY_INITIALIZE_OUTPUT(v2f_meta, o);
    o.pos = UnityMetaVertexPosition(v.vertex, v.uv1.xy, v.uv2.xy, unity_LightmapST, unity_DynamicLightmapST);
    o.uv = TexCoords(v);
#ifdef EDITOR_VISUALIZATION
    if (unity_VisualizationMode == EDITORVIZ_TEXTURE) {
        o.vizUV = UnityMetaVizUV(unity_EditorViz_UVIndex, v.uv0.xy, v.uv1.xy, v.uv2.xy, unity_EditorViz_Texture_ST);
    } else if (unity_VisualizationMode == EDITORVIZ_SHOWLIGHTMASK) {
        o.vizUV = v.uv1.xy * unity_LightmapST.xy + unity_LightmapST.zw;
        o.lightCoord = mul(unity_EditorViz_WorldToLight, mul(unity_ObjectToWorld, float4(v.vertex.xyz, 1)));
    }
#endif
    return o;
}

// Albedo the lightmapper bounces: diffuse + specular * roughness / 2 (rough specular surfaces
// scatter part of their specular light diffusely).
half3 UnityLightmappingAlbedo(half3 diffuse, half3 specular, half smoothness) {
    half roughness = SmoothnessToRoughness(smoothness);
    return diffuse + specular * roughness * 0.5;
}

float4 frag_meta(v2f_meta i) : SV_Target {
    FragmentCommonData data = UNITY_SETUP_BRDF_INPUT(i.uv);
    UnityMetaInput o;
    UNITY_INITIALIZE_OUTPUT(UnityMetaInput, o);
    o.Albedo = UnityLightmappingAlbedo(data.diffColor, data.specColor, data.smoothness);
    o.SpecularColor = data.specColor;
    o.Emission = Emission(i.uv.xy);
#ifdef EDITOR_VISUALIZATION
    o.VizUV = i.vizUV;
    o.LightCoord = i.lightCoord;
#endif
    return UnityMetaFragment(o);
}

#endif // UNITY_STANDARD_META_INCLUDED
