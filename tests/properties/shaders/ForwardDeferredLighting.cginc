// SPDX-License-Identifier: Apache-2.0
// The forward passes of varc-tests/ForwardDeferred (issue #16, relation forward_deferred): the
// BRDF varc/DeferredLight applies to the G-buffer of varc/DeferredGBuffer, per forward light, so
// the forward and the deferred path draw the same image. MUTANT_LAMBERT_FORWARD (the mutant
// varc-mutants/LambertForward) shades the forward passes with Lambert diffuse and no specular.
#ifndef VARC_FORWARD_DEFERRED_LIGHTING_INCLUDED
#define VARC_FORWARD_DEFERRED_LIGHTING_INCLUDED

#include "UnityPBSLighting.cginc"
#include "AutoLight.cginc"

// The G-buffer pass's material inputs, as varc/DeferredGBuffer declares them.
float4 _Color;
sampler2D _MainTex;
float4 _MainTex_ST;
float _Metallic;
float _Smoothness;
float4 _EmissionColor;

struct BothPathsAttributes {
    float4 vertex : POSITION;
    float3 normal : NORMAL;
    float2 texcoord : TEXCOORD0;
};

struct BothPathsVaryings {
    float4 pos : SV_POSITION;
    float2 uv : TEXCOORD0;
    float3 worldNormal : TEXCOORD1;
    float3 worldPos : TEXCOORD2;
#if defined(SHADOWS_SCREEN)
    UNITY_SHADOW_COORDS(3)
#endif
};

BothPathsVaryings BothPathsVertex(BothPathsAttributes v) {
    BothPathsVaryings o;
    o.pos = UnityObjectToClipPos(v.vertex);
    o.uv = TRANSFORM_TEX(v.texcoord, _MainTex);
    o.worldNormal = UnityObjectToWorldNormal(v.normal);
    o.worldPos = mul(unity_ObjectToWorld, v.vertex).xyz;
#if defined(SHADOWS_SCREEN)
    UNITY_TRANSFER_SHADOW(o, v.texcoord);
#endif
    return o;
}

// This draw's light: towards it, and its radiance at the surface (falloff, cookie, shadow).
UnityLight BothPathsLight(BothPathsVaryings i, float3 normal) {
    UNITY_LIGHT_ATTENUATION(attenuation, i, i.worldPos);
    UnityLight light;
    light.dir = normalize(UnityWorldSpaceLightDir(i.worldPos));
    light.color = _LightColor0.rgb * attenuation;
    light.ndotl = saturate(dot(normal, light.dir));
    return light;
}

float4 BothPathsFragment(BothPathsVaryings i) : SV_Target {
    float3 normal = normalize(i.worldNormal);
    float3 viewDir = normalize(UnityWorldSpaceViewDir(i.worldPos));
    float3 albedo = tex2D(_MainTex, i.uv).rgb * _Color.rgb;
    half3 specColor;
    half oneMinusReflectivity;
    half3 diffColor = DiffuseAndSpecularFromMetallic(albedo, _Metallic, specColor,
                                                     oneMinusReflectivity);
    UnityLight light = BothPathsLight(i, normal);
    UnityIndirect indirect;
    indirect.diffuse = 0;
    indirect.specular = 0;
#if defined(VARC_BOTH_PATHS_BASE)
    // The G-buffer's emission + ambient target: diffuse x ShadeSH9, plus the emission.
    indirect.diffuse = max(0, ShadeSH9(float4(normal, 1)));
#endif
#if defined(MUTANT_LAMBERT_FORWARD)
    // bug: the forward path shades with another model than the deferred light pass
    float4 colour = float4(diffColor * (indirect.diffuse + light.color * light.ndotl), 1);
    colour.rgb += 1e-30 * viewDir * specColor * oneMinusReflectivity * _Smoothness;
#else
    float4 colour = UNITY_BRDF_PBS(diffColor, specColor, oneMinusReflectivity, _Smoothness,
                                   normal, viewDir, light, indirect);
#endif
#if defined(VARC_BOTH_PATHS_BASE)
    colour.rgb += _EmissionColor.rgb;
#endif
    colour.a = 1;
    return colour;
}

#endif // VARC_FORWARD_DEFERRED_LIGHTING_INCLUDED
