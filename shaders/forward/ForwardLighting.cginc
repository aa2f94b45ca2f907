// SPDX-License-Identifier: Apache-2.0
// varc lighting library: the program shared by both passes of Forward.shader. The pass selects
// its lights with VARC_FORWARD_BASE (base pass) and the variant's light keyword (add pass).
//   colour = UNITY_BRDF_PBS(diffuse, specular, 1 - reflectivity, smoothness, n, v, direct, indirect)
//   direct.dir   = normalize(_WorldSpaceLightPos0.xyz - worldPos * _WorldSpaceLightPos0.w)
//   direct.color = _LightColor0.rgb * attenuation (UNITY_LIGHT_ATTENUATION, per light keyword)
//   indirect.diffuse = base pass only: Shade4PointLights (VERTEXLIGHT_ON) + max(0, ShadeSH9(n))
//   indirect.specular = 0
// docs/LIGHTING.md §8.1 states the same for a CPU reference. Written for varc.
#ifndef VARC_FORWARD_LIGHTING_INCLUDED
#define VARC_FORWARD_LIGHTING_INCLUDED

#include "UnityPBSLighting.cginc"
#include "AutoLight.cginc"

float4 _Color;
sampler2D _MainTex;
float4 _MainTex_ST;
float _Metallic;
float _Smoothness;

struct ForwardAttributes {
    float4 vertex : POSITION;
    float3 normal : NORMAL;
    float2 texcoord : TEXCOORD0;
};

struct ForwardVaryings {
    float4 pos : SV_POSITION;
    float2 uv : TEXCOORD0;
    float3 worldNormal : TEXCOORD1;
    float3 worldPos : TEXCOORD2;
#if defined(VARC_FORWARD_BASE) && defined(VERTEXLIGHT_ON)
    float3 vertexLights : TEXCOORD3;   // diffuse irradiance of the four vertex lights
#endif
#if defined(SHADOWS_SCREEN)
    // The screen position the shadow mask is read at; spot and point shadows are computed from
    // worldPos (UNITY_LIGHT_ATTENUATION), so they interpolate nothing more.
    UNITY_SHADOW_COORDS(4)
#endif
};

ForwardVaryings ForwardVertex(ForwardAttributes v) {
    ForwardVaryings o;
    o.pos = UnityObjectToClipPos(v.vertex);
    o.worldPos = mul(unity_ObjectToWorld, v.vertex).xyz;
    o.worldNormal = UnityObjectToWorldNormal(v.normal);
    o.uv = TRANSFORM_TEX(v.texcoord, _MainTex);
#if defined(SHADOWS_SCREEN)
    UNITY_TRANSFER_SHADOW(o, v.texcoord);
#endif
#if defined(VARC_FORWARD_BASE) && defined(VERTEXLIGHT_ON)
    // Evaluated per vertex and interpolated, as Unity's vertex lights are.
    o.vertexLights = Shade4PointLights(
        unity_4LightPosX0, unity_4LightPosY0, unity_4LightPosZ0,
        unity_LightColor[0].rgb, unity_LightColor[1].rgb, unity_LightColor[2].rgb, unity_LightColor[3].rgb,
        unity_4LightAtten0, o.worldPos, o.worldNormal);
#endif
    return o;
}

// The pixel light of this draw: direction towards it and the radiance reaching the surface.
UnityLight ForwardPixelLight(ForwardVaryings i, float3 normal) {
    UnityLight light;
    // w = 0: directional, xyz is the unit direction towards the light; w = 1: a position.
    light.dir = normalize(UnityWorldSpaceLightDir(i.worldPos));
    UNITY_LIGHT_ATTENUATION(attenuation, i, i.worldPos);
    light.color = _LightColor0.rgb * attenuation;
    light.ndotl = saturate(dot(normal, light.dir));
    return light;
}

UnityIndirect ForwardIndirectLight(ForwardVaryings i, float3 normal) {
    UnityIndirect indirect;
    indirect.diffuse = 0;
    indirect.specular = 0;
#if defined(VARC_FORWARD_BASE)
    #if defined(VERTEXLIGHT_ON)
    indirect.diffuse = i.vertexLights;
    #endif
    indirect.diffuse += max(0, ShadeSH9(float4(normal, 1)));
#endif
    return indirect;
}

float4 ForwardFragment(ForwardVaryings i) : SV_Target {
    float3 normal = normalize(i.worldNormal);
    float3 viewDir = normalize(UnityWorldSpaceViewDir(i.worldPos));
    float3 albedo = tex2D(_MainTex, i.uv).rgb * _Color.rgb;

    half3 specColor;
    half oneMinusReflectivity;
    half3 diffColor = DiffuseAndSpecularFromMetallic(albedo, _Metallic, specColor, oneMinusReflectivity);

    float4 colour = UNITY_BRDF_PBS(diffColor, specColor, oneMinusReflectivity, _Smoothness,
                                   normal, viewDir, ForwardPixelLight(i, normal),
                                   ForwardIndirectLight(i, normal));
    colour.a = 1;
    return colour;
}

#endif // VARC_FORWARD_LIGHTING_INCLUDED
