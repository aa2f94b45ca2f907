// SPDX-License-Identifier: Apache-2.0
// A copy of shaders/forward/ForwardLighting.cginc for the property mutation tests (issue #16):
// unchanged unless the including shader defines one MUTANT_* macro, each a deliberate bug that
// docs/PROPERTIES.md says which relation must catch, or a model the classification must name
// (MUTANT_SQRT_COLOUR). Keep it in step with the library copy.
#ifndef VARC_MUTANT_LIGHTING_INCLUDED
#define VARC_MUTANT_LIGHTING_INCLUDED

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
#if defined(MUTANT_UNNORMALISED_NORMAL)
    o.worldNormal = mul(v.normal, (float3x3)unity_WorldToObject);  // bug: never normalised
#else
    o.worldNormal = UnityObjectToWorldNormal(v.normal);
#endif
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
#if defined(MUTANT_NO_ATTENUATION)
    // bug: attenuation (falloff, cookie) forgotten; 1e-30 x attenuation vanishes next to any
    // light colour but keeps the shadow coordinates read (the validation layer reports vertex
    // outputs a fragment program drops)
    light.color = _LightColor0.rgb + 1e-30 * attenuation;
#elif defined(MUTANT_COOKIE_IGNORED) && (defined(DIRECTIONAL_COOKIE) || defined(SPOT))
    // bug: the cookie is not sampled; a spot keeps only its distance falloff
    #if defined(SPOT)
    float3 lightCoord = mul(unity_WorldToLight, float4(i.worldPos, 1)).xyz;
    light.color = _LightColor0.rgb * UnitySpotAttenuate(lightCoord) + 1e-30 * attenuation;
    #else
    light.color = _LightColor0.rgb + 1e-30 * attenuation;
    #endif
#elif defined(MUTANT_INTENSITY_IGNORED)
    // bug: the light's intensity is ignored (its colour scaled to a maximum of 1)
    light.color = _LightColor0.rgb /
                  max(1e-4, max(_LightColor0.r, max(_LightColor0.g, _LightColor0.b))) * attenuation;
#elif defined(MUTANT_LIGHT_ZERO)
    // bug: the light is read but scaled to nothing a half float can hold (1e-30, not 0, which
    // the optimiser would fold away with the reads): every pass draws black
    light.color = 1e-30 * _LightColor0.rgb * attenuation;
#elif defined(MUTANT_SQRT_COLOUR)
    light.color = sqrt(_LightColor0.rgb) * attenuation;  // a non-linear model by design
#elif defined(MUTANT_POINT_COOKIE_NO_FALLOFF) && defined(POINT_COOKIE)
    // bug: the cube cookie alone, the distance falloff (_LightTextureB0) forgotten
    float3 lightCoord = mul(unity_WorldToLight, float4(i.worldPos, 1)).xyz;
    light.color = _LightColor0.rgb * texCUBE(_LightTexture0, lightCoord).w + 1e-30 * attenuation;
#elif defined(MUTANT_NAN_SPOT) && defined(SPOT)
    light.color = _LightColor0.rgb * attenuation * sqrt(-1.0 - attenuation);  // bug: NaN here
#else
    light.color = _LightColor0.rgb * attenuation;
#endif
#if defined(MUTANT_WORLD_X_LIGHT)
    light.color *= light.dir.x >= 0 ? 1.0 : 0.5;  // bug: depends on the world x axis
#endif
#if defined(MUTANT_FIXED_DIRECTION)
    // bug: every light shines from straight above, wherever it is (the falloff still follows its
    // position); symmetric about the y axis, so only a light below the surface tells
    light.dir = float3(0, 1, 0);
#endif
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
#if defined(MUTANT_UNNORMALISED_NORMAL)
    float3 normal = i.worldNormal;  // bug: the interpolated normal is not normalised
#else
    float3 normal = normalize(i.worldNormal);
#endif
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

#endif // VARC_MUTANT_LIGHTING_INCLUDED
