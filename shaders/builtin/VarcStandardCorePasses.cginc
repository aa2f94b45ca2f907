// SPDX-License-Identifier: Apache-2.0
// varc built-in, part of UnityStandardCore.cginc (included by it): the Standard shader's
// forward base, forward add and deferred programs with Unity's interpolator structs (layout in
// UnityStandardCore.cginc's header comment). Written for varc from the documented behaviour of
// the Standard shader.
#if !defined(UNITY_STANDARD_CORE_INCLUDED)
#error "VarcStandardCorePasses.cginc is a part of UnityStandardCore.cginc: include that file instead"
#elif !defined(VARC_STANDARD_CORE_PASSES_INCLUDED)
#define VARC_STANDARD_CORE_PASSES_INCLUDED

// The world-space frame rows (tangent, binormal, normal) of a vertex; without a tangent only
// the normal row is set.
inline void VarcVertexTangentFrame(VertexInput v, float3 normalWorld, out float4 rows[3]) {
    rows[0] = 0;
    rows[1] = 0;
    rows[2] = float4(normalWorld, 0);
#ifdef _TANGENT_TO_WORLD
    float3x3 t2w = CreateTangentToWorldPerVertex(normalWorld, UnityObjectToWorldDir(v.tangent.xyz), v.tangent.w);
    rows[0].xyz = t2w[0];
    rows[1].xyz = t2w[1];
    rows[2].xyz = t2w[2];
#endif
}
// The camera-to-vertex direction in tangent space (object space rotated by the tangent frame).
inline half3 VarcViewDirForParallax(VertexInput v) {
#ifdef _PARALLAXMAP
    TANGENT_SPACE_ROTATION;
    return mul(rotation, ObjSpaceViewDir(v.vertex));
#else
    return 0;
#endif
}

// ---------------------------------------------------------------------------------------------
// Forward base.
// ---------------------------------------------------------------------------------------------
struct VertexOutputForwardBase {
    UNITY_POSITION(pos);
    float4 tex : TEXCOORD0;
    float4 eyeVec : TEXCOORD1;                        // xyz: camera-to-vertex; w: fog coordinate
    float4 tangentToWorldAndPackedData[3] : TEXCOORD2; // TEXCOORD2..4
    half4 ambientOrLightmapUV : TEXCOORD5;            // SH ambient or lightmap uvs
    UNITY_LIGHTING_COORDS(6, 7)
#if UNITY_REQUIRE_FRAG_WORLDPOS && !UNITY_PACK_WORLDPOS_WITH_TANGENT
    float3 posWorld : TEXCOORD8;
#endif
    UNITY_VERTEX_INPUT_INSTANCE_ID
    UNITY_VERTEX_OUTPUT_STEREO
};

VertexOutputForwardBase vertForwardBase(VertexInput v) {
    UNITY_SETUP_INSTANCE_ID(v);
    VertexOutputForwardBase o;
    UNITY_INITIALIZE_OUTPUT(VertexOutputForwardBase, o);
    UNITY_TRANSFER_INSTANCE_ID(v, o);
    UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);
    float4 posWorld = mul(unity_ObjectToWorld, v.vertex);
    o.pos = UnityObjectToClipPos(v.vertex);
    o.tex = TexCoords(v);
    o.eyeVec.xyz = NormalizePerVertexNormal(posWorld.xyz - _WorldSpaceCameraPos);
    float3 normalWorld = UnityObjectToWorldNormal(v.normal);
    VarcVertexTangentFrame(v, normalWorld, o.tangentToWorldAndPackedData);
#if UNITY_REQUIRE_FRAG_WORLDPOS
    #if UNITY_PACK_WORLDPOS_WITH_TANGENT
    o.tangentToWorldAndPackedData[0].w = posWorld.x;
    o.tangentToWorldAndPackedData[1].w = posWorld.y;
    o.tangentToWorldAndPackedData[2].w = posWorld.z;
    #else
    o.posWorld = posWorld.xyz;
    #endif
#endif
#ifdef _PARALLAXMAP
    half3 viewDirForParallax = VarcViewDirForParallax(v);
    o.tangentToWorldAndPackedData[0].w = viewDirForParallax.x;
    o.tangentToWorldAndPackedData[1].w = viewDirForParallax.y;
    o.tangentToWorldAndPackedData[2].w = viewDirForParallax.z;
#endif
    UNITY_TRANSFER_LIGHTING(o, v.uv1);
    o.ambientOrLightmapUV = VertexGIForward(v, posWorld.xyz, normalWorld);
    UNITY_TRANSFER_FOG_COMBINED_WITH_EYE_VEC(o, o.pos);
    return o;
}

half4 fragForwardBaseInternal(VertexOutputForwardBase i) {
    UNITY_APPLY_DITHER_CROSSFADE(i.pos.xy);
    FRAGMENT_SETUP(s)
    UNITY_SETUP_INSTANCE_ID(i);
    UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX(i);
    UnityLight mainLight = MainLight();
    UNITY_LIGHT_ATTENUATION(atten, i, s.posWorld);
    half occlusion = Occlusion(i.tex.xy);
    UnityGI gi = FragmentGI(s, occlusion, i.ambientOrLightmapUV, atten, mainLight);
    half4 c = UNITY_BRDF_PBS(s.diffColor, s.specColor, s.oneMinusReflectivity, s.smoothness, s.normalWorld, -s.eyeVec, gi.light, gi.indirect);
    c.rgb += Emission(i.tex.xy);
    UNITY_EXTRACT_FOG_FROM_EYE_VEC(i);
    UNITY_APPLY_FOG(_unity_fogCoord, c.rgb);
    return OutputForward(c, s.alpha);
}
half4 fragForwardBase(VertexOutputForwardBase i) : SV_Target { return fragForwardBaseInternal(i); }

// ---------------------------------------------------------------------------------------------
// Forward add: one light per draw, no indirect light.
// ---------------------------------------------------------------------------------------------
struct VertexOutputForwardAdd {
    UNITY_POSITION(pos);
    float4 tex : TEXCOORD0;
    float4 eyeVec : TEXCOORD1;                     // xyz: camera-to-vertex; w: fog coordinate
    float4 tangentToWorldAndLightDir[3] : TEXCOORD2; // TEXCOORD2..4; w: direction to the light
    float3 posWorld : TEXCOORD5;
    UNITY_LIGHTING_COORDS(6, 7)
#if defined(_PARALLAXMAP)
    half3 viewDirForParallax : TEXCOORD8;
#endif
    UNITY_VERTEX_OUTPUT_STEREO
};

VertexOutputForwardAdd vertForwardAdd(VertexInput v) {
    UNITY_SETUP_INSTANCE_ID(v);
    VertexOutputForwardAdd o;
    UNITY_INITIALIZE_OUTPUT(VertexOutputForwardAdd, o);
    UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);
    float4 posWorld = mul(unity_ObjectToWorld, v.vertex);
    o.pos = UnityObjectToClipPos(v.vertex);
    o.tex = TexCoords(v);
    o.eyeVec.xyz = NormalizePerVertexNormal(posWorld.xyz - _WorldSpaceCameraPos);
    o.posWorld = posWorld.xyz;
    float3 normalWorld = UnityObjectToWorldNormal(v.normal);
    VarcVertexTangentFrame(v, normalWorld, o.tangentToWorldAndLightDir);
    UNITY_TRANSFER_LIGHTING(o, v.uv1);
    float3 lightDir = _WorldSpaceLightPos0.xyz - posWorld.xyz * _WorldSpaceLightPos0.w;
#ifndef USING_DIRECTIONAL_LIGHT
    lightDir = NormalizePerVertexNormal(lightDir);
#endif
    o.tangentToWorldAndLightDir[0].w = lightDir.x;
    o.tangentToWorldAndLightDir[1].w = lightDir.y;
    o.tangentToWorldAndLightDir[2].w = lightDir.z;
#ifdef _PARALLAXMAP
    o.viewDirForParallax = VarcViewDirForParallax(v);
#endif
    UNITY_TRANSFER_FOG_COMBINED_WITH_EYE_VEC(o, o.pos);
    return o;
}

half4 fragForwardAddInternal(VertexOutputForwardAdd i) {
    UNITY_APPLY_DITHER_CROSSFADE(i.pos.xy);
    UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX(i);
    FRAGMENT_SETUP_FWDADD(s)
    UNITY_LIGHT_ATTENUATION(atten, i, s.posWorld)
    UnityLight light = AdditiveLight(IN_LIGHTDIR_FWDADD(i), atten);
    UnityIndirect noIndirect = ZeroIndirect();
    half4 c = UNITY_BRDF_PBS(s.diffColor, s.specColor, s.oneMinusReflectivity, s.smoothness, s.normalWorld, -s.eyeVec, light, noIndirect);
    UNITY_EXTRACT_FOG_FROM_EYE_VEC(i);
    UNITY_APPLY_FOG_COLOR(_unity_fogCoord, c.rgb, half4(0, 0, 0, 0)); // additive: fog towards black
    return OutputForward(c, s.alpha);
}
half4 fragForwardAdd(VertexOutputForwardAdd i) : SV_Target { return fragForwardAddInternal(i); }

// ---------------------------------------------------------------------------------------------
// Deferred G-buffer pass. RT3 receives emission + indirect light (SH, lightmaps, and reflection
// probes unless UNITY_ENABLE_REFLECTION_BUFFERS leaves them to the deferred reflections pass):
// linear with UNITY_HDR_ON, exp2(-c) otherwise (the LDR light-buffer encoding).
// ---------------------------------------------------------------------------------------------
struct VertexOutputDeferred {
    UNITY_POSITION(pos);
    float4 tex : TEXCOORD0;
    float3 eyeVec : TEXCOORD1;
    float4 tangentToWorldAndPackedData[3] : TEXCOORD2; // TEXCOORD2..4
    half4 ambientOrLightmapUV : TEXCOORD5;
#if UNITY_REQUIRE_FRAG_WORLDPOS && !UNITY_PACK_WORLDPOS_WITH_TANGENT
    float3 posWorld : TEXCOORD6;
#endif
    UNITY_VERTEX_INPUT_INSTANCE_ID
    UNITY_VERTEX_OUTPUT_STEREO
};

VertexOutputDeferred vertDeferred(VertexInput v) {
    UNITY_SETUP_INSTANCE_ID(v);
    VertexOutputDeferred o;
    UNITY_INITIALIZE_OUTPUT(VertexOutputDeferred, o);
    UNITY_TRANSFER_INSTANCE_ID(v, o);
    UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);
    float4 posWorld = mul(unity_ObjectToWorld, v.vertex);
    o.pos = UnityObjectToClipPos(v.vertex);
    o.tex = TexCoords(v);
    o.eyeVec = NormalizePerVertexNormal(posWorld.xyz - _WorldSpaceCameraPos);
    float3 normalWorld = UnityObjectToWorldNormal(v.normal);
    VarcVertexTangentFrame(v, normalWorld, o.tangentToWorldAndPackedData);
#if UNITY_REQUIRE_FRAG_WORLDPOS
    #if UNITY_PACK_WORLDPOS_WITH_TANGENT
    o.tangentToWorldAndPackedData[0].w = posWorld.x;
    o.tangentToWorldAndPackedData[1].w = posWorld.y;
    o.tangentToWorldAndPackedData[2].w = posWorld.z;
    #else
    o.posWorld = posWorld.xyz;
    #endif
#endif
    // Unlike the forward pass, the deferred one has no per-vertex lights.
#ifdef LIGHTMAP_ON
    o.ambientOrLightmapUV.xy = v.uv1.xy * unity_LightmapST.xy + unity_LightmapST.zw;
#elif UNITY_SHOULD_SAMPLE_SH
    o.ambientOrLightmapUV.rgb = ShadeSHPerVertex(normalWorld, 0);
#endif
#ifdef DYNAMICLIGHTMAP_ON
    o.ambientOrLightmapUV.zw = v.uv2.xy * unity_DynamicLightmapST.xy + unity_DynamicLightmapST.zw;
#endif
#ifdef _PARALLAXMAP
    half3 viewDirForParallax = VarcViewDirForParallax(v);
    o.tangentToWorldAndPackedData[0].w = viewDirForParallax.x;
    o.tangentToWorldAndPackedData[1].w = viewDirForParallax.y;
    o.tangentToWorldAndPackedData[2].w = viewDirForParallax.z;
#endif
    return o;
}

void fragDeferred(VertexOutputDeferred i,
    out half4 outGBuffer0 : SV_Target0,
    out half4 outGBuffer1 : SV_Target1,
    out half4 outGBuffer2 : SV_Target2,
    out half4 outEmission : SV_Target3
#if defined(SHADOWS_SHADOWMASK) && (UNITY_ALLOWED_MRT_COUNT > 4)
    , out half4 outShadowMask : SV_Target4
#endif
    )
{
    UNITY_APPLY_DITHER_CROSSFADE(i.pos.xy);
    FRAGMENT_SETUP(s)
    UNITY_SETUP_INSTANCE_ID(i);
#if UNITY_ENABLE_REFLECTION_BUFFERS
    bool sampleReflectionsInDeferred = false;
#else
    bool sampleReflectionsInDeferred = true;
#endif
    half occlusion = Occlusion(i.tex.xy);
    UnityGI gi = FragmentGI(s, occlusion, i.ambientOrLightmapUV, 1.0, DummyLight(), sampleReflectionsInDeferred);
    half3 emissiveColor = UNITY_BRDF_PBS(s.diffColor, s.specColor, s.oneMinusReflectivity, s.smoothness, s.normalWorld, -s.eyeVec, gi.light, gi.indirect).rgb;
    emissiveColor += Emission(i.tex.xy);
#ifndef UNITY_HDR_ON
    emissiveColor = exp2(-emissiveColor);
#endif
    UnityStandardData data;
    data.diffuseColor = s.diffColor;
    data.occlusion = occlusion;
    data.specularColor = s.specColor;
    data.smoothness = s.smoothness;
    data.normalWorld = s.normalWorld;
    UnityStandardDataToGbuffer(data, outGBuffer0, outGBuffer1, outGBuffer2);
    outEmission = half4(emissiveColor, 1);
#if defined(SHADOWS_SHADOWMASK) && (UNITY_ALLOWED_MRT_COUNT > 4)
    outShadowMask = UnityGetRawBakedOcclusions(i.ambientOrLightmapUV.xy, IN_WORLDPOS(i));
#endif
}

#endif // VARC_STANDARD_CORE_PASSES_INCLUDED
