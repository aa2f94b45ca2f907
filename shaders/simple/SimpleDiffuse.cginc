// SPDX-License-Identifier: Apache-2.0
// varc lighting library: the program of SimpleDiffuse.shader (both passes). With albedo
// a = tex(_MainTex) * _Color, n the unit world normal and l the unit direction to the light:
//   add pass:  rgb = a * _LightColor0.rgb * saturate(dot(n, l)) * LIGHT_ATTENUATION
//   base pass: the same for the main directional light, plus a * (ambient + vertexLights)
// LIGHT_ATTENUATION reads the light coordinates interpolated from the vertex
// (TRANSFER_VERTEX_TO_FRAGMENT) and the legacy shadow term without distance fade
// (docs/LIGHTING.md §3, §6). Alpha = a.a. Written for varc.
#ifndef VARC_SIMPLE_DIFFUSE_INCLUDED
#define VARC_SIMPLE_DIFFUSE_INCLUDED

#include "UnityCG.cginc"
#include "Lighting.cginc"
#include "AutoLight.cginc"

sampler2D _MainTex;
float4 _MainTex_ST;
fixed4 _Color;

// The AutoLight TRANSFER macros read the vertex input as `v.vertex`.
struct appdata_simple {
    float4 vertex : POSITION;
    float3 normal : NORMAL;
    float2 texcoord : TEXCOORD0;
};

struct v2f_simple {
    float4 pos : SV_POSITION;     // named `pos`: TRANSFER_SHADOW (SHADOWS_SCREEN) reads it
    float2 uv : TEXCOORD0;
    float3 worldNormal : TEXCOORD1;
    float3 worldPos : TEXCOORD2;
    LIGHTING_COORDS(3, 4)
#if defined(VARC_SIMPLE_BASE)
    float3 ambientAndVertexLights : TEXCOORD5;
#endif
};

v2f_simple SimpleVertex(appdata_simple v) {
    v2f_simple o;
    o.pos = UnityObjectToClipPos(v.vertex);
    o.uv = TRANSFORM_TEX(v.texcoord, _MainTex);
    o.worldNormal = UnityObjectToWorldNormal(v.normal);
    o.worldPos = mul(unity_ObjectToWorld, v.vertex).xyz;
    TRANSFER_VERTEX_TO_FRAGMENT(o);
#if defined(VARC_SIMPLE_BASE)
    #if defined(LIGHTPROBE_SH)
    o.ambientAndVertexLights = max(0, ShadeSH9(float4(o.worldNormal, 1)));
    #else
    o.ambientAndVertexLights = UNITY_LIGHTMODEL_AMBIENT.rgb;
    #endif
    #if defined(VERTEXLIGHT_ON)
    o.ambientAndVertexLights += Shade4PointLights(
        unity_4LightPosX0, unity_4LightPosY0, unity_4LightPosZ0,
        unity_LightColor[0].rgb, unity_LightColor[1].rgb, unity_LightColor[2].rgb, unity_LightColor[3].rgb,
        unity_4LightAtten0, o.worldPos, o.worldNormal);
    #endif
#endif
    return o;
}

fixed4 SimpleFragment(v2f_simple i) : SV_Target {
    fixed4 albedo = tex2D(_MainTex, i.uv) * _Color;
    float3 normal = normalize(i.worldNormal);
    float3 lightDir = normalize(UnityWorldSpaceLightDir(i.worldPos));
    fixed atten = LIGHT_ATTENUATION(i);

    fixed4 c;
    c.rgb = albedo.rgb * _LightColor0.rgb * (saturate(dot(normal, lightDir)) * atten);
#if defined(VARC_SIMPLE_BASE)
    c.rgb += albedo.rgb * i.ambientAndVertexLights;
#endif
    c.a = albedo.a;
    return c;
}

#endif // VARC_SIMPLE_DIFFUSE_INCLUDED
