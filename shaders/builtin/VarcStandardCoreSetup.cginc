// SPDX-License-Identifier: Apache-2.0
// varc built-in, part of UnityStandardCore.cginc (included by it, not meant to be included
// alone): the per-pixel surface setup of the Standard shader (workflows, FragmentSetup), its
// global illumination (VertexGIForward, FragmentGI) and the forward output alpha.
// Written for varc from the documented behaviour of the Standard shader.
#if !defined(UNITY_STANDARD_CORE_INCLUDED)
#error "VarcStandardCoreSetup.cginc is a part of UnityStandardCore.cginc: include that file instead"
#elif !defined(VARC_STANDARD_CORE_SETUP_INCLUDED)
#define VARC_STANDARD_CORE_SETUP_INCLUDED

// ---------------------------------------------------------------------------------------------
// Workflows: albedo, reflectivity and smoothness of one texel.
// ---------------------------------------------------------------------------------------------
inline FragmentCommonData SpecularSetup(float4 i_tex) {
    half4 specGloss = SpecularGloss(i_tex.xy);
    half oneMinusReflectivity;
    half3 diffColor = EnergyConservationBetweenDiffuseAndSpecular(Albedo(i_tex), specGloss.rgb, oneMinusReflectivity);
    FragmentCommonData o = (FragmentCommonData)0;
    o.diffColor = diffColor;
    o.specColor = specGloss.rgb;
    o.oneMinusReflectivity = oneMinusReflectivity;
    o.smoothness = specGloss.a;
    return o;
}

// Metallic from MetallicGloss (x) or MetallicRough (x, roughness workflow), smoothness (y).
inline FragmentCommonData VarcMetallicSetupFrom(float4 i_tex, half2 metallicGloss) {
    half3 specColor;
    half oneMinusReflectivity;
    half3 diffColor = DiffuseAndSpecularFromMetallic(Albedo(i_tex), metallicGloss.x, specColor, oneMinusReflectivity);
    FragmentCommonData o = (FragmentCommonData)0;
    o.diffColor = diffColor;
    o.specColor = specColor;
    o.oneMinusReflectivity = oneMinusReflectivity;
    o.smoothness = metallicGloss.y;
    return o;
}
inline FragmentCommonData MetallicSetup(float4 i_tex) { return VarcMetallicSetupFrom(i_tex, MetallicGloss(i_tex.xy)); }
// The roughness workflow ("Autodesk Interactive"): smoothness = 1 - roughness.
inline FragmentCommonData RoughnessSetup(float4 i_tex) { return VarcMetallicSetupFrom(i_tex, MetallicRough(i_tex.xy)); }

// Parallax shifts i_tex (the caller's uvs change with it), then alpha test, workflow setup,
// shading normal, unit eye vector and premultiplied alpha.
inline FragmentCommonData FragmentSetup(inout float4 i_tex, float3 i_eyeVec, half3 i_viewDirForParallax,
                                        float4 tangentToWorld[3], float3 i_posWorld) {
    i_tex = Parallax(i_tex, i_viewDirForParallax);
    half alpha = Alpha(i_tex.xy);
#if defined(_ALPHATEST_ON)
    clip(alpha - _Cutoff);
#endif
    FragmentCommonData o = UNITY_SETUP_BRDF_INPUT(i_tex);
    o.normalWorld = PerPixelWorldNormal(i_tex, tangentToWorld);
    o.eyeVec = NormalizePerPixelNormal(i_eyeVec);
    o.posWorld = i_posWorld;
    o.diffColor = PreMultiplyAlpha(o.diffColor, alpha, o.oneMinusReflectivity, o.alpha);
    return o;
}

// ---------------------------------------------------------------------------------------------
// Global illumination.
// ---------------------------------------------------------------------------------------------
// Per-vertex part: the lightmap uvs (baked xy, realtime zw) when lightmapped, else the vertex
// lights (VERTEXLIGHT_ON) plus the SH part Unity evaluates per vertex, in rgb.
inline half4 VertexGIForward(VertexInput v, float3 posWorld, half3 normalWorld) {
    half4 ambientOrLightmapUV = 0;
#ifdef LIGHTMAP_ON
    ambientOrLightmapUV.xy = v.uv1.xy * unity_LightmapST.xy + unity_LightmapST.zw;
#elif UNITY_SHOULD_SAMPLE_SH
    #ifdef VERTEXLIGHT_ON
    ambientOrLightmapUV.rgb = Shade4PointLights(unity_4LightPosX0, unity_4LightPosY0, unity_4LightPosZ0,
        unity_LightColor[0].rgb, unity_LightColor[1].rgb, unity_LightColor[2].rgb, unity_LightColor[3].rgb,
        unity_4LightAtten0, posWorld, normalWorld);
    #endif
    ambientOrLightmapUV.rgb = ShadeSHPerVertex(normalWorld, ambientOrLightmapUV.rgb);
#endif
#ifdef DYNAMICLIGHTMAP_ON
    ambientOrLightmapUV.zw = v.uv2.xy * unity_DynamicLightmapST.xy + unity_DynamicLightmapST.zw;
#endif
    return ambientOrLightmapUV;
}

// Indirect light of the pixel: UnityGlobalIllumination with both reflection probes, or diffuse
// only (reflections false: the deferred reflections pass adds the probes later).
inline UnityGI FragmentGI(FragmentCommonData s, half occlusion, half4 i_ambientOrLightmapUV, half atten,
                          UnityLight light, bool reflections) {
    UnityGIInput d;
    UNITY_INITIALIZE_OUTPUT(UnityGIInput, d);
    d.light = light;
    d.worldPos = s.posWorld;
    d.worldViewDir = -s.eyeVec;
    d.atten = atten;
#if defined(LIGHTMAP_ON) || defined(DYNAMICLIGHTMAP_ON)
    d.ambient = 0;
    d.lightmapUV = i_ambientOrLightmapUV;
#else
    d.ambient = i_ambientOrLightmapUV.rgb;
    d.lightmapUV = 0;
#endif
    d.boxMin[0] = unity_SpecCube0_BoxMin;
    d.boxMax[0] = unity_SpecCube0_BoxMax;
    d.probePosition[0] = unity_SpecCube0_ProbePosition;
    d.probeHDR[0] = unity_SpecCube0_HDR;
    d.boxMin[1] = unity_SpecCube1_BoxMin;
    d.boxMax[1] = unity_SpecCube1_BoxMax;
    d.probePosition[1] = unity_SpecCube1_ProbePosition;
    d.probeHDR[1] = unity_SpecCube1_HDR;
    if (reflections) {
        Unity_GlossyEnvironmentData g = UnityGlossyEnvironmentSetup(s.smoothness, -s.eyeVec, s.normalWorld, s.specColor);
        return UnityGlobalIllumination(d, occlusion, s.normalWorld, g);
    }
    return UnityGlobalIllumination(d, occlusion, s.normalWorld);
}
inline UnityGI FragmentGI(FragmentCommonData s, half occlusion, half4 i_ambientOrLightmapUV, half atten,
                          UnityLight light) {
    return FragmentGI(s, occlusion, i_ambientOrLightmapUV, atten, light, true);
}
// Unity 5's form: the surface given by its position, smoothness, normal and eye vector.
inline UnityGI FragmentGI(float3 posWorld, half occlusion, half4 i_ambientOrLightmapUV, half atten, half smoothness,
                          half3 normalWorld, half3 eyeVec, UnityLight light, bool reflections) {
    FragmentCommonData s = (FragmentCommonData)0;
    s.smoothness = smoothness;
    s.normalWorld = normalWorld;
    s.eyeVec = eyeVec;
    s.posWorld = posWorld;
    return FragmentGI(s, occlusion, i_ambientOrLightmapUV, atten, light, reflections);
}
inline UnityGI FragmentGI(float3 posWorld, half occlusion, half4 i_ambientOrLightmapUV, half atten, half smoothness,
                          half3 normalWorld, half3 eyeVec, UnityLight light) {
    return FragmentGI(posWorld, occlusion, i_ambientOrLightmapUV, atten, smoothness, normalWorld, eyeVec, light, true);
}

// Alpha of the forward output: the surface alpha when blending, 1 otherwise.
half4 OutputForward(half4 output, half alphaFromSurface) {
#if defined(_ALPHABLEND_ON) || defined(_ALPHAPREMULTIPLY_ON)
    output.a = alphaFromSurface;
#else
    UNITY_OPAQUE_ALPHA(output.a);
#endif
    return output;
}

#endif // VARC_STANDARD_CORE_SETUP_INCLUDED
