// SPDX-License-Identifier: Apache-2.0
// varc built-in: the shadow-collector pass macros of Unity 4 era shaders (SHADOW_COLLECTOR_PASS,
// included by UnityCG.cginc): a pass that writes the main directional light's shadow of each
// pixel. Unity 5+ collects screen-space shadows itself and varc's runtime never runs such a
// pass; the macros compile and compute the shadow from the cascade-0 map. Written for varc.
#ifndef VARC_SHADOW_COLLECTOR_INCLUDED
#define VARC_SHADOW_COLLECTOR_INCLUDED

// The directional light's shadow map, unless the program declared it (SHADOWMAPSAMPLER_DEFINED).
#if defined(SHADOW_COLLECTOR_PASS) && !defined(SHADOWMAPSAMPLER_DEFINED)
UNITY_DECLARE_SHADOWMAP(_ShadowMapTexture);
#define SHADOWMAPSAMPLER_DEFINED
#endif

#if defined(SHADOW_COLLECTOR_PASS)
// pos, the world position and the view depth (w), in TEXCOORD4 as in Unity (whose TEXCOORD0-3
// held cascade coordinates): the program's own interpolators start at TEXCOORD5.
#define V2F_SHADOW_COLLECTOR float4 pos : SV_POSITION; float4 _WorldPosViewZ : TEXCOORD4
#define TRANSFER_SHADOW_COLLECTOR(o) o.pos = UnityObjectToClipPos(v.vertex); o._WorldPosViewZ = float4(mul(unity_ObjectToWorld, float4(v.vertex.xyz, 1.0)).xyz, -UnityObjectToViewPos(v.vertex.xyz).z);
// coord = (u, v, depth) in the map: 1 = lit.
#define SAMPLE_SHADOW_COLLECTOR_SHADOW(coord) UNITY_SAMPLE_SHADOW(_ShadowMapTexture, (coord).xyz)
// The shadow of cascade 0 at the pixel's world position, faded by shadowFade, strength applied;
// |weights| (cascade selection) is accepted and not used: varc renders one cascade.
#define COMPUTE_SHADOW_COLLECTOR_SHADOW(i, weights, shadowFade) \
    float4 coord = mul(unity_WorldToShadow[0], float4((i)._WorldPosViewZ.xyz, 1.0)); \
    float shadow = lerp(_LightShadowData.r, 1.0, SAMPLE_SHADOW_COLLECTOR_SHADOW(coord)); \
    shadow = saturate(shadow + (shadowFade));
#endif
// The fragment program's body: the shadow, faded with distance as UnityComputeShadowFade does.
#define SHADOW_COLLECTOR_FRAGMENT(i) \
    float4 unused_weights = float4(1, 0, 0, 0); \
    float shadowFade = saturate(lerp((i)._WorldPosViewZ.w, distance((i)._WorldPosViewZ.xyz, unity_ShadowFadeCenterAndType.xyz), unity_ShadowFadeCenterAndType.w) * _LightShadowData.z + _LightShadowData.w); \
    COMPUTE_SHADOW_COLLECTOR_SHADOW(i, unused_weights, shadowFade) \
    return shadow;

#endif // VARC_SHADOW_COLLECTOR_INCLUDED
