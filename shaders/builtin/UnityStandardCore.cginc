// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityStandardCore.cginc. The Standard shader's per-pixel passes on top of
// UnityStandardInput.cginc and varc's BRDF (UNITY_BRDF_PBS), with the interpolator layout and the
// helper API of Unity's file (so shaders that reuse vertForwardBase & co. or read the structs'
// members keep working):
//   forward base  vertForwardBase / fragForwardBase   main light + SH / lightmaps + probes + emission
//   forward add   vertForwardAdd / fragForwardAdd     one additional light per draw
//   deferred      vertDeferred / fragDeferred         G-buffer (UnityGBuffer.cginc) + emission/ambient
// Packing (as Unity does it): tangentToWorldAndPackedData[k].xyz = tangent, binormal, normal
// rows; their .w hold the tangent-space view direction (_PARALLAXMAP) or the world position
// (UNITY_PACK_WORLDPOS_WITH_TANGENT); the forward-add frame's .w hold the light direction.
// ambientOrLightmapUV = per-vertex SH ambient (rgb) without lightmaps, else the baked (xy) and
// realtime (zw) lightmap uvs. Written for varc from the documented behaviour of the Standard
// shader; not derived from Unity's files.
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

// Fog coordinate carried in eyeVec.w (Unity 2018.3+'s UnityCG macros; defined here when
// UnityCG.cginc does not provide them).
#ifndef UNITY_TRANSFER_FOG_COMBINED_WITH_EYE_VEC
    #if defined(FOG_LINEAR) || defined(FOG_EXP) || defined(FOG_EXP2)
        #define UNITY_TRANSFER_FOG_COMBINED_WITH_EYE_VEC(o, outpos) o.eyeVec.w = (outpos).w
        #define UNITY_EXTRACT_FOG_FROM_EYE_VEC(name) float _unity_fogCoord = name.eyeVec.w
    #else
        #define UNITY_TRANSFER_FOG_COMBINED_WITH_EYE_VEC(o, outpos)
        #define UNITY_EXTRACT_FOG_FROM_EYE_VEC(name)
    #endif
#endif

// ---------------------------------------------------------------------------------------------
// Normals and lights.
// ---------------------------------------------------------------------------------------------
// The full path normalises per pixel (the vertex value is passed on as is); the simple path
// normalises per vertex.
half3 NormalizePerVertexNormal(float3 n) {
#if UNITY_STANDARD_SIMPLE
    return normalize(n);
#else
    return n;
#endif
}
float3 NormalizePerPixelNormal(float3 n) {
#if UNITY_STANDARD_SIMPLE
    return n;
#else
    return normalize(n);
#endif
}

// The main (directional) light of the forward base pass: colour and direction towards the light.
UnityLight MainLight() {
    UnityLight l;
    l.color = _LightColor0.rgb;
    l.dir = _WorldSpaceLightPos0.xyz;
    l.ndotl = 0;
    return l;
}
// The light of a forward-add pass: colour times attenuation; point/spot directions normalised.
UnityLight AdditiveLight(half3 lightDir, half atten) {
    UnityLight l;
    l.color = _LightColor0.rgb * atten;
    l.dir = lightDir;
#ifndef USING_DIRECTIONAL_LIGHT
    l.dir = NormalizePerPixelNormal(l.dir);
#endif
    l.ndotl = 0;
    return l;
}
// No light: black, pointing up (deferred passes light later).
UnityLight DummyLight() {
    UnityLight l;
    l.color = 0;
    l.dir = half3(0, 1, 0);
    l.ndotl = 0;
    return l;
}
UnityIndirect ZeroIndirect() {
    UnityIndirect ind;
    ind.diffuse = 0;
    ind.specular = 0;
    return ind;
}

// Rows tangent, binormal, normal of the interpolated frame; re-orthonormalised (Gram-Schmidt
// from the normal) when UNITY_TANGENT_ORTHONORMALIZE is on.
half3x3 ExtractTangentToWorldPerPixel(half4 tan2world[3]) {
    half3 t = tan2world[0].xyz;
    half3 b = tan2world[1].xyz;
    half3 n = normalize(tan2world[2].xyz);
#if UNITY_TANGENT_ORTHONORMALIZE
    t = normalize(t - n * dot(t, n));
    half3 newB = cross(n, t);
    b = newB * sign(dot(newB, b));
#endif
    return half3x3(t, b, n);
}
// The interpolated normal (third row), normalised.
half3 WorldNormal(half4 tan2world[3]) { return normalize(tan2world[2].xyz); }

// Shading normal: the tangent-space normal map in the interpolated frame, else the interpolated
// normal.
float3 PerPixelWorldNormal(float4 i_tex, float4 tangentToWorld[3]) {
#ifdef _NORMALMAP
    half3 t = tangentToWorld[0].xyz;
    half3 b = tangentToWorld[1].xyz;
    half3 n = tangentToWorld[2].xyz;
    #if UNITY_TANGENT_ORTHONORMALIZE
    n = NormalizePerPixelNormal(n);
    t = normalize(t - n * dot(t, n));
    half3 newB = cross(n, t);
    b = newB * sign(dot(newB, b));
    #endif
    half3 nt = NormalInTangentSpace(i_tex);
    return NormalizePerPixelNormal(t * nt.x + b * nt.y + n * nt.z);
#else
    return normalize(tangentToWorld[2].xyz);
#endif
}

// Unpacking the interpolators (see the file comment).
#ifdef _PARALLAXMAP
    #define IN_VIEWDIR4PARALLAX(i) NormalizePerPixelNormal(half3(i.tangentToWorldAndPackedData[0].w, i.tangentToWorldAndPackedData[1].w, i.tangentToWorldAndPackedData[2].w))
    #define IN_VIEWDIR4PARALLAX_FWDADD(i) NormalizePerPixelNormal(i.viewDirForParallax.xyz)
#else
    #define IN_VIEWDIR4PARALLAX(i) half3(0, 0, 0)
    #define IN_VIEWDIR4PARALLAX_FWDADD(i) half3(0, 0, 0)
#endif
#if UNITY_REQUIRE_FRAG_WORLDPOS
    #if UNITY_PACK_WORLDPOS_WITH_TANGENT
        #define IN_WORLDPOS(i) float3(i.tangentToWorldAndPackedData[0].w, i.tangentToWorldAndPackedData[1].w, i.tangentToWorldAndPackedData[2].w)
    #else
        #define IN_WORLDPOS(i) i.posWorld
    #endif
    #define IN_WORLDPOS_FWDADD(i) i.posWorld
#else
    #define IN_WORLDPOS(i) half3(0, 0, 0)
    #define IN_WORLDPOS_FWDADD(i) half3(0, 0, 0)
#endif
#define IN_LIGHTDIR_FWDADD(i) half3(i.tangentToWorldAndLightDir[0].w, i.tangentToWorldAndLightDir[1].w, i.tangentToWorldAndLightDir[2].w)

#define FRAGMENT_SETUP(x) FragmentCommonData x = \
    FragmentSetup(i.tex, i.eyeVec.xyz, IN_VIEWDIR4PARALLAX(i), i.tangentToWorldAndPackedData, IN_WORLDPOS(i));
#define FRAGMENT_SETUP_FWDADD(x) FragmentCommonData x = \
    FragmentSetup(i.tex, i.eyeVec.xyz, IN_VIEWDIR4PARALLAX_FWDADD(i), i.tangentToWorldAndLightDir, IN_WORLDPOS_FWDADD(i));

// ---------------------------------------------------------------------------------------------
// Surface data of one pixel.
// ---------------------------------------------------------------------------------------------
struct FragmentCommonData {
    half3 diffColor, specColor;
    // Only oneMinusReflectivity and smoothness reach the BRDF (the simple path also its own).
    half oneMinusReflectivity, smoothness;
    float3 normalWorld;
    float3 eyeVec;      // unit vector from the camera to the surface
    half alpha;
    float3 posWorld;
#if UNITY_STANDARD_SIMPLE
    half3 reflUVW;             // world reflection vector
    half3 tangentSpaceNormal;  // normal map value (lighting in tangent space)
#endif
};

#include "VarcStandardCoreSetup.cginc"
#include "VarcStandardCorePasses.cginc"

#endif // UNITY_STANDARD_CORE_INCLUDED
