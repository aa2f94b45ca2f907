// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityStandardCore.cginc. A compact implementation of Unity's Standard shader
// passes on top of UnityStandardInput.cginc and varc's BRDF (UNITY_BRDF_PBS):
//   forward base  vertBase / fragBase   main directional light + SH / lightmaps + probes + emission
//   forward add   vertAdd / fragAdd     one additional light per draw (AutoLight attenuation)
//   deferred      vertDeferred / fragDeferred   G-buffer (UnityGBuffer.cginc layout) + emission/ambient
// Workflow: UNITY_SETUP_BRDF_INPUT (MetallicSetup or SpecularSetup; default SpecularSetup).
// Written for varc from the documented behaviour of the Standard shader; not derived from Unity's
// files.
#ifndef UNITY_STANDARD_CORE_INCLUDED
#define UNITY_STANDARD_CORE_INCLUDED

#include "UnityCG.cginc"
#include "UnityShaderVariables.cginc"
#include "UnityStandardConfig.cginc"
#include "UnityStandardInput.cginc"
#include "UnityPBSLighting.cginc"
#include "UnityStandardUtils.cginc"
#include "UnityGBuffer.cginc"
#include "UnityStandardBRDF.cginc"
#include "AutoLight.cginc"

#ifndef UNITY_SETUP_BRDF_INPUT
#define UNITY_SETUP_BRDF_INPUT SpecularSetup
#endif

// ---------------------------------------------------------------------------------------------
// Surface data of one pixel.
// ---------------------------------------------------------------------------------------------
struct FragmentCommonData {
    half3 diffColor, specColor;
    half oneMinusReflectivity, smoothness;
    float3 normalWorld;
    float3 eyeVec;      // unit vector from the camera to the surface
    half alpha;
    float3 posWorld;
};

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

inline FragmentCommonData MetallicSetup(float4 i_tex) {
    half2 metallicGloss = MetallicGloss(i_tex.xy);
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

// Shading normal: the normal map in the interpolated tangent frame (tangentWorld.w = bitangent
// sign), else the interpolated normal.
float3 PerPixelWorldNormal(float4 i_tex, float3 normalWorld, float4 tangentWorld) {
    float3 n = normalize(normalWorld);
#ifdef _NORMALMAP
    float3 t = normalize(tangentWorld.xyz);
    float3 b = cross(n, t) * tangentWorld.w;
    half3 nt = NormalInTangentSpace(i_tex);
    n = normalize(t * nt.x + b * nt.y + n * nt.z);
#endif
    return n;
}

// Parallax (tangent-space view direction), alpha test, workflow setup, normal, premultiply.
inline FragmentCommonData FragmentSetup(inout float4 i_tex, float3 posWorld, float3 normalWorld, float4 tangentWorld) {
#if defined(_PARALLAXMAP)
    float3 n = normalize(normalWorld);
    float3 t = normalize(tangentWorld.xyz);
    float3 b = cross(n, t) * tangentWorld.w;
    float3 toCamera = _WorldSpaceCameraPos - posWorld;
    i_tex = Parallax(i_tex, half3(dot(toCamera, t), dot(toCamera, b), dot(toCamera, n)));
#endif
    half alpha = Alpha(i_tex.xy);
#if defined(_ALPHATEST_ON)
    clip(alpha - _Cutoff);
#endif
    FragmentCommonData o = UNITY_SETUP_BRDF_INPUT(i_tex);
    o.normalWorld = PerPixelWorldNormal(i_tex, normalWorld, tangentWorld);
    o.eyeVec = normalize(posWorld - _WorldSpaceCameraPos);
    o.posWorld = posWorld;
    o.diffColor = PreMultiplyAlpha(o.diffColor, alpha, o.oneMinusReflectivity, o.alpha);
    return o;
}

// Indirect light of the pixel (UnityGlobalIllumination with both reflection probes).
inline UnityGI FragmentGI(FragmentCommonData s, half occlusion, half3 ambient, float4 lightmapUV, half atten, UnityLight light) {
    UnityGIInput d;
    d.light = light;
    d.worldPos = s.posWorld;
    d.worldViewDir = -s.eyeVec;
    d.atten = atten;
    d.ambient = ambient;
    d.lightmapUV = lightmapUV;
    d.boxMin[0] = unity_SpecCube0_BoxMin;
    d.boxMax[0] = unity_SpecCube0_BoxMax;
    d.probePosition[0] = unity_SpecCube0_ProbePosition;
    d.probeHDR[0] = unity_SpecCube0_HDR;
    d.boxMin[1] = unity_SpecCube1_BoxMin;
    d.boxMax[1] = unity_SpecCube1_BoxMax;
    d.probePosition[1] = unity_SpecCube1_ProbePosition;
    d.probeHDR[1] = unity_SpecCube1_HDR;
    Unity_GlossyEnvironmentData g = UnityGlossyEnvironmentSetup(s.smoothness, -s.eyeVec, s.normalWorld, s.specColor);
    return UnityGlobalIllumination(d, occlusion, s.normalWorld, g);
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

// Per-vertex ambient: vertex lights (VERTEXLIGHT_ON) + the SH part Unity evaluates per vertex.
inline half3 VertexAmbient(float3 posWorld, half3 normalWorld) {
    half3 ambient = 0;
#if UNITY_SHOULD_SAMPLE_SH
    #ifdef VERTEXLIGHT_ON
    ambient = Shade4PointLights(unity_4LightPosX0, unity_4LightPosY0, unity_4LightPosZ0,
        unity_LightColor[0].rgb, unity_LightColor[1].rgb, unity_LightColor[2].rgb, unity_LightColor[3].rgb,
        unity_4LightAtten0, posWorld, normalWorld);
    #endif
    ambient = ShadeSHPerVertex(normalWorld, ambient);
#endif
    return ambient;
}
// xy = baked lightmap uv (LIGHTMAP_ON), zw = realtime lightmap uv (DYNAMICLIGHTMAP_ON).
inline float4 VertexLightmapUV(VertexInput v) {
    float4 uv = 0;
#ifdef LIGHTMAP_ON
    uv.xy = v.uv1.xy * unity_LightmapST.xy + unity_LightmapST.zw;
#endif
#ifdef DYNAMICLIGHTMAP_ON
    uv.zw = v.uv2.xy * unity_DynamicLightmapST.xy + unity_DynamicLightmapST.zw;
#endif
    return uv;
}

// ---------------------------------------------------------------------------------------------
// Forward base.
// ---------------------------------------------------------------------------------------------
struct VertexOutputForwardBase {
    UNITY_POSITION(pos);
    float4 tex : TEXCOORD0;
    float3 posWorld : TEXCOORD1;
    float3 normalWorld : TEXCOORD2;
    float4 tangentWorld : TEXCOORD3;
    half3 ambient : TEXCOORD4;
    float4 lightmapUV : TEXCOORD5;
    UNITY_LIGHTING_COORDS(6, 7)
    UNITY_FOG_COORDS(8)
};

VertexOutputForwardBase vertForwardBase(VertexInput v) {
    UNITY_SETUP_INSTANCE_ID(v);
    VertexOutputForwardBase o;
    UNITY_INITIALIZE_OUTPUT(VertexOutputForwardBase, o);
    float4 posWorld = mul(unity_ObjectToWorld, v.vertex);
    o.pos = UnityObjectToClipPos(v.vertex);
    o.posWorld = posWorld.xyz;
    o.tex = TexCoords(v);
    o.normalWorld = UnityObjectToWorldNormal(v.normal);
#ifdef _TANGENT_TO_WORLD
    o.tangentWorld = float4(UnityObjectToWorldDir(v.tangent.xyz), v.tangent.w * unity_WorldTransformParams.w);
#endif
    o.ambient = VertexAmbient(posWorld.xyz, o.normalWorld);
    o.lightmapUV = VertexLightmapUV(v);
    UNITY_TRANSFER_LIGHTING(o, v.uv1);
    UNITY_TRANSFER_FOG(o, o.pos);
    return o;
}

half4 fragForwardBaseInternal(VertexOutputForwardBase i) {
    float4 tex = i.tex;
    FragmentCommonData s = FragmentSetup(tex, i.posWorld, i.normalWorld, i.tangentWorld);
    UNITY_LIGHT_ATTENUATION(atten, i, s.posWorld);
    UnityLight mainLight;
    mainLight.color = _LightColor0.rgb;
    mainLight.dir = _WorldSpaceLightPos0.xyz;
    mainLight.ndotl = 0;
    half occlusion = Occlusion(tex.xy);
    UnityGI gi = FragmentGI(s, occlusion, i.ambient, i.lightmapUV, atten, mainLight);
    half4 c = UNITY_BRDF_PBS(s.diffColor, s.specColor, s.oneMinusReflectivity, s.smoothness, s.normalWorld, -s.eyeVec, gi.light, gi.indirect);
    c.rgb += Emission(tex.xy);
    UNITY_APPLY_FOG(i.fogCoord, c);
    return OutputForward(c, s.alpha);
}
half4 fragForwardBase(VertexOutputForwardBase i) : SV_Target { return fragForwardBaseInternal(i); }

// ---------------------------------------------------------------------------------------------
// Forward add: one light per draw, no indirect light.
// ---------------------------------------------------------------------------------------------
struct VertexOutputForwardAdd {
    UNITY_POSITION(pos);
    float4 tex : TEXCOORD0;
    float3 posWorld : TEXCOORD1;
    float3 normalWorld : TEXCOORD2;
    float4 tangentWorld : TEXCOORD3;
    UNITY_LIGHTING_COORDS(4, 5)
    UNITY_FOG_COORDS(6)
};

VertexOutputForwardAdd vertForwardAdd(VertexInput v) {
    UNITY_SETUP_INSTANCE_ID(v);
    VertexOutputForwardAdd o;
    UNITY_INITIALIZE_OUTPUT(VertexOutputForwardAdd, o);
    float4 posWorld = mul(unity_ObjectToWorld, v.vertex);
    o.pos = UnityObjectToClipPos(v.vertex);
    o.posWorld = posWorld.xyz;
    o.tex = TexCoords(v);
    o.normalWorld = UnityObjectToWorldNormal(v.normal);
#ifdef _TANGENT_TO_WORLD
    o.tangentWorld = float4(UnityObjectToWorldDir(v.tangent.xyz), v.tangent.w * unity_WorldTransformParams.w);
#endif
    UNITY_TRANSFER_LIGHTING(o, v.uv1);
    UNITY_TRANSFER_FOG(o, o.pos);
    return o;
}

half4 fragForwardAddInternal(VertexOutputForwardAdd i) {
    float4 tex = i.tex;
    FragmentCommonData s = FragmentSetup(tex, i.posWorld, i.normalWorld, i.tangentWorld);
    UNITY_LIGHT_ATTENUATION(atten, i, s.posWorld);
    UnityLight light;
    light.color = _LightColor0.rgb * atten;
    light.dir = normalize(UnityWorldSpaceLightDir(s.posWorld));
    light.ndotl = 0;
    UnityIndirect noIndirect;
    noIndirect.diffuse = 0;
    noIndirect.specular = 0;
    half4 c = UNITY_BRDF_PBS(s.diffColor, s.specColor, s.oneMinusReflectivity, s.smoothness, s.normalWorld, -s.eyeVec, light, noIndirect);
    UNITY_APPLY_FOG(i.fogCoord, c);   // towards black in ForwardAdd
    return OutputForward(c, s.alpha);
}
half4 fragForwardAdd(VertexOutputForwardAdd i) : SV_Target { return fragForwardAddInternal(i); }

// ---------------------------------------------------------------------------------------------
// Deferred G-buffer pass. RT3 receives emission + indirect light (SH, lightmaps, reflection
// probes): linear with UNITY_HDR_ON, exp2(-c) otherwise (the LDR light-buffer encoding).
// ---------------------------------------------------------------------------------------------
struct VertexOutputDeferred {
    UNITY_POSITION(pos);
    float4 tex : TEXCOORD0;
    float3 posWorld : TEXCOORD1;
    float3 normalWorld : TEXCOORD2;
    float4 tangentWorld : TEXCOORD3;
    half3 ambient : TEXCOORD4;
    float4 lightmapUV : TEXCOORD5;
};

VertexOutputDeferred vertDeferred(VertexInput v) {
    UNITY_SETUP_INSTANCE_ID(v);
    VertexOutputDeferred o;
    UNITY_INITIALIZE_OUTPUT(VertexOutputDeferred, o);
    float4 posWorld = mul(unity_ObjectToWorld, v.vertex);
    o.pos = UnityObjectToClipPos(v.vertex);
    o.posWorld = posWorld.xyz;
    o.tex = TexCoords(v);
    o.normalWorld = UnityObjectToWorldNormal(v.normal);
#ifdef _TANGENT_TO_WORLD
    o.tangentWorld = float4(UnityObjectToWorldDir(v.tangent.xyz), v.tangent.w * unity_WorldTransformParams.w);
#endif
    o.ambient = VertexAmbient(posWorld.xyz, o.normalWorld);
    o.lightmapUV = VertexLightmapUV(v);
    return o;
}

void fragDeferred(VertexOutputDeferred i,
    out half4 outGBuffer0 : SV_Target0,
    out half4 outGBuffer1 : SV_Target1,
    out half4 outGBuffer2 : SV_Target2,
    out half4 outEmission : SV_Target3)
{
    float4 tex = i.tex;
    FragmentCommonData s = FragmentSetup(tex, i.posWorld, i.normalWorld, i.tangentWorld);
    UnityLight noLight;
    noLight.color = 0;
    noLight.dir = half3(0, 1, 0);
    noLight.ndotl = 0;
    half occlusion = Occlusion(tex.xy);
    UnityGI gi = FragmentGI(s, occlusion, i.ambient, i.lightmapUV, 1.0, noLight);
    half3 emissiveColor = UNITY_BRDF_PBS(s.diffColor, s.specColor, s.oneMinusReflectivity, s.smoothness, s.normalWorld, -s.eyeVec, gi.light, gi.indirect).rgb;
    emissiveColor += Emission(tex.xy);
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
}

#endif // UNITY_STANDARD_CORE_INCLUDED
