// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityBuiltin2xTreeLibrary.cginc. Vertex programs of the soft-occlusion trees of
// the terrain engine (Nature/Tree Soft Occlusion Bark and Leaves): bent and squashed by the
// terrain, lit per vertex by ambient light plus up to four lights through each vertex's baked
// occlusion direction. Written for varc from the documented behaviour; not derived from Unity.
#ifndef UNITY_BUILTIN_2X_TREE_LIBRARY_INCLUDED
#define UNITY_BUILTIN_2X_TREE_LIBRARY_INCLUDED

#include "HLSLSupport.cginc"
#include "UnityCG.cginc"
#include "TerrainEngine.cginc"

fixed4 _Color;
float _Occlusion;      // strength of the directional occlusion term
float _AO;             // strength of the ambient occlusion term
float _BaseLight;      // light every vertex gets from each light
float _HalfOverCutoff; // 0.5 / alpha cut-off of the leaves
// _CameraToWorld: UnityShaderVariables.cginc (unity_CameraToWorld).
#if defined(USE_CUSTOM_LIGHT_DIR)
float3 _TerrainTreeLightDirections[4];  // world space, towards each light
float4 _TerrainTreeLightColors[4];
#endif

struct v2f {
    float4 pos : SV_POSITION;
    float4 uv : TEXCOORD0;
    half4 color : TEXCOORD1;
    UNITY_FOG_COORDS(2)
    UNITY_VERTEX_OUTPUT_STEREO
};

// Ambient light plus, for each of four lights, its colour times (occlusion + _BaseLight) times
// its attenuation, where occlusion = max(0, dot(tangent, (lightDir * _Occlusion, _AO))): the
// tree's tangent holds the baked occlusion direction (xyz) and ambient occlusion (w).
// The lights are the legacy vertex lights (unity_LightPosition/Color/Atten, view space) or, with
// USE_CUSTOM_LIGHT_DIR, _TerrainTreeLightDirections/_TerrainTreeLightColors.
half4 VarcTreeSoftOcclusionLight(float4 vertex, float4 occlusion) {
    float3 viewPos = UnityObjectToViewPos(vertex);
    float4 light = UNITY_LIGHTMODEL_AMBIENT;
    for (int i = 0; i < 4; i++) {
        float atten = 1.0;
        float3 lightDir;
        float4 lightColor;
#if defined(USE_CUSTOM_LIGHT_DIR)
        lightDir = mul((float3x3)unity_WorldToObject, _TerrainTreeLightDirections[i]);
        lightColor = _TerrainTreeLightColors[i];
#else
        float3 toLight = unity_LightPosition[i].xyz - viewPos * unity_LightPosition[i].w;
        float lengthSq = dot(toLight, toLight);
        atten = 1.0 / (1.0 + lengthSq * unity_LightAtten[i].z);
        // View space (right-handed, -z forward) to object space.
        lightDir = mul((float3x3)unity_WorldToObject, mul((float3x3)unity_MatrixInvV, normalize(toLight)));
        lightColor = unity_LightColor[i];
#endif
        float occ = max(0, dot(occlusion, float4(normalize(lightDir) * _Occlusion, _AO)));
        light += lightColor * ((occ + _BaseLight) * atten);
    }
    return light;
}

v2f leaves(appdata_tree v) {
    v2f o;
    UNITY_INITIALIZE_OUTPUT(v2f, o);
    UNITY_SETUP_INSTANCE_ID(v);
    TerrainAnimateTree(v.vertex, v.color.w);
    o.pos = UnityObjectToClipPos(v.vertex);
    o.uv = v.texcoord;
    o.color = VarcTreeSoftOcclusionLight(v.vertex, v.tangent) * _Color * _TreeInstanceColor;
    o.color.a = 0.5 * _HalfOverCutoff;
    UNITY_TRANSFER_FOG(o, o.pos);
    return o;
}

v2f bark(appdata_tree v) {
    v2f o;
    UNITY_INITIALIZE_OUTPUT(v2f, o);
    UNITY_SETUP_INSTANCE_ID(v);
    TerrainAnimateTree(v.vertex, v.color.w);
    o.pos = UnityObjectToClipPos(v.vertex);
    o.uv = v.texcoord;
    o.color = VarcTreeSoftOcclusionLight(v.vertex, v.tangent) * _Color * _TreeInstanceColor;
    o.color.a = 1.0;
    UNITY_TRANSFER_FOG(o, o.pos);
    return o;
}

#endif // UNITY_BUILTIN_2X_TREE_LIBRARY_INCLUDED
