// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityStandardCoreForwardSimple.cginc. The "simple" forward path of the Standard
// shader (UNITY_STANDARD_SIMPLE, Unity's low-end tier): per-vertex eye and reflection vectors,
// Fresnel and ambient, lighting in tangent space when a normal map is on, and a one-lookup
// specular (BRDF3DirectSimple) on the reflection vector instead of the full GGX BRDF. Surface
// inputs and GI come from UnityStandardCore.cginc. Written for varc from the documented
// behaviour of the Standard shader; not derived from Unity's file.
//
// Per-vertex data (VertexOutputBaseSimple): eyeVec.xyz = unit camera-to-vertex vector, eyeVec.w =
// the material's reflectivity when it is uniform (no gloss map); normalWorld.w = per-vertex
// Fresnel term (1 - dot(n, -eyeVec))^4; fogCoord.yzw = the world reflection vector (no normal
// map, specular highlights on). Parallax mapping and detail normal maps are not part of this
// path (as in Unity's simple tier).
#ifndef UNITY_STANDARD_CORE_FORWARD_SIMPLE_INCLUDED
#define UNITY_STANDARD_CORE_FORWARD_SIMPLE_INCLUDED

#include "UnityStandardCore.cginc"

// Specular highlights unless the material turns them off (_SPECULARHIGHLIGHTS_OFF).
#ifndef SPECULAR_HIGHLIGHTS
    #if defined(_SPECULARHIGHLIGHTS_OFF)
        #define SPECULAR_HIGHLIGHTS 0
    #else
        #define SPECULAR_HIGHLIGHTS 1
    #endif
#endif
// Whether reflectivity and smoothness come from a texture (else they are uniform per material
// and the grazing term can be computed per vertex).
#if defined(_SPECGLOSSMAP) || defined(_METALLICGLOSSMAP)
    #define GLOSSMAP 1
#else
    #define GLOSSMAP 0
#endif
// Fog coordinate of |vectype| at TEXCOORD|idx|, declared even without fog: the simple path
// packs the reflection vector into its other components.
#ifndef UNITY_FOG_COORDS_PACKED
    #define UNITY_FOG_COORDS_PACKED(idx, vectype) vectype fogCoord : TEXCOORD##idx;
#endif

// Token pasting that expands its arguments first: UNIFORM_REFLECTIVITY() calls
// SpecularSetup_Reflectivity, MetallicSetup_Reflectivity or RoughnessSetup_Reflectivity.
#define JOIN2(a, b) a##b
#define JOIN(a, b) JOIN2(a, b)
#define UNIFORM_REFLECTIVITY JOIN(UNITY_SETUP_BRDF_INPUT, _Reflectivity)

// Reflectivity (1 - oneMinusReflectivity) of a material without gloss map, per workflow.
half MetallicSetup_Reflectivity() { return 1.0h - OneMinusReflectivityFromMetallic(_Metallic); }
half SpecularSetup_Reflectivity() { return SpecularStrength(_SpecColor.rgb); }
half RoughnessSetup_Reflectivity() { return MetallicSetup_Reflectivity(); }

#ifdef _NORMALMAP
// v in the frame (tangent, binormal, normal): (dot(t, v), dot(b, v), dot(n, v)).
half3 TransformToTangentSpace(half3 tangent, half3 binormal, half3 normal, half3 v) {
    return half3(dot(tangent, v), dot(binormal, v), dot(normal, v));
}
// The light direction and eye vector in the vertex's tangent frame: t = normalize(vTangent.xyz),
// b = cross(n, t) * vTangent.w (n = normalWorld, unit).
void TangentSpaceLightingInput(half3 normalWorld, half4 vTangent, half3 lightDirWorld, half3 eyeVecWorld,
                               out half3 tangentSpaceLightDir, out half3 tangentSpaceEyeVec) {
    half3 tangentWorld = normalize(vTangent.xyz);
    half3 binormalWorld = cross(normalWorld, tangentWorld) * vTangent.w;
    tangentSpaceLightDir = TransformToTangentSpace(tangentWorld, binormalWorld, normalWorld, lightDirWorld);
    tangentSpaceEyeVec = normalize(TransformToTangentSpace(tangentWorld, binormalWorld, normalWorld, eyeVecWorld));
}
#endif

// ---------------------------------------------------------------------------------------------
// Forward base.
// ---------------------------------------------------------------------------------------------
struct VertexOutputBaseSimple {
    UNITY_POSITION(pos);
    float4 tex : TEXCOORD0;
    half4 eyeVec : TEXCOORD1;              // w: uniform reflectivity
    half4 ambientOrLightmapUV : TEXCOORD2; // SH / vertex lights, or lightmap uv
    SHADOW_COORDS(3)
    UNITY_FOG_COORDS_PACKED(4, half4)      // yzw: reflection vector
    half4 normalWorld : TEXCOORD5;         // w: Fresnel term
#ifdef _NORMALMAP
    half3 tangentSpaceLightDir : TEXCOORD6;
    #if SPECULAR_HIGHLIGHTS
    half3 tangentSpaceEyeVec : TEXCOORD7;
    #endif
#endif
#if UNITY_REQUIRE_FRAG_WORLDPOS
    float3 posWorld : TEXCOORD8;
#endif
    UNITY_VERTEX_OUTPUT_STEREO
};

// The reflection vector the specular highlight is evaluated on, in the space of
// LightDirForSpecular: tangent space with a normal map, world space (per vertex) otherwise.
#if !SPECULAR_HIGHLIGHTS
    #define REFLECTVEC_FOR_SPECULAR(i, s) half3(0, 0, 0)
#elif defined(_NORMALMAP)
    #define REFLECTVEC_FOR_SPECULAR(i, s) reflect(i.tangentSpaceEyeVec, NormalInTangentSpace(i.tex))
#else
    #define REFLECTVEC_FOR_SPECULAR(i, s) (i.fogCoord.yzw)
#endif

VertexOutputBaseSimple vertForwardBaseSimple(VertexInput v) {
    UNITY_SETUP_INSTANCE_ID(v);
    VertexOutputBaseSimple o;
    UNITY_INITIALIZE_OUTPUT(VertexOutputBaseSimple, o);
    UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);
    float4 posWorld = mul(unity_ObjectToWorld, v.vertex);
    o.pos = UnityObjectToClipPos(v.vertex);
    o.tex = TexCoords(v);
#if UNITY_REQUIRE_FRAG_WORLDPOS
    o.posWorld = posWorld.xyz;
#endif
    half3 eyeVec = normalize(posWorld.xyz - _WorldSpaceCameraPos);
    half3 normalWorld = UnityObjectToWorldNormal(v.normal);
    o.normalWorld.xyz = normalWorld;
    o.eyeVec.xyz = eyeVec;
#ifdef _NORMALMAP
    half3 tangentSpaceEyeVec;
    TangentSpaceLightingInput(normalWorld, v.tangent, _WorldSpaceLightPos0.xyz, eyeVec, o.tangentSpaceLightDir, tangentSpaceEyeVec);
    #if SPECULAR_HIGHLIGHTS
    o.tangentSpaceEyeVec = tangentSpaceEyeVec;
    #endif
#endif
    TRANSFER_SHADOW(o);
    o.ambientOrLightmapUV = VertexGIForward(v, posWorld.xyz, normalWorld);
    o.normalWorld.w = Pow4(1 - saturate(dot(normalWorld, -eyeVec)));
#if !GLOSSMAP
    o.eyeVec.w = UNIFORM_REFLECTIVITY();
#endif
    UNITY_TRANSFER_FOG(o, o.pos);
#if !defined(_NORMALMAP) && SPECULAR_HIGHLIGHTS
    o.fogCoord.yzw = reflect(eyeVec, normalWorld);
#endif
    return o;
}

// Surface data: alpha test, workflow setup, the interpolated (vertex) normal, premultiply.
FragmentCommonData FragmentSetupSimple(VertexOutputBaseSimple i) {
    half alpha = Alpha(i.tex.xy);
#if defined(_ALPHATEST_ON)
    clip(alpha - _Cutoff);
#endif
    FragmentCommonData s = UNITY_SETUP_BRDF_INPUT(i.tex);
    s.normalWorld = normalize(i.normalWorld.xyz);
    s.eyeVec = normalize(i.eyeVec.xyz);
#if UNITY_REQUIRE_FRAG_WORLDPOS
    s.posWorld = i.posWorld;
#else
    s.posWorld = _WorldSpaceCameraPos;
#endif
    s.diffColor = PreMultiplyAlpha(s.diffColor, alpha, s.oneMinusReflectivity, s.alpha);
    return s;
}

UnityLight MainLightSimple(VertexOutputBaseSimple i, FragmentCommonData s) {
    UnityLight mainLight;
    mainLight.color = _LightColor0.rgb;
    mainLight.dir = _WorldSpaceLightPos0.xyz;
    mainLight.ndotl = LambertTerm(s.normalWorld, mainLight.dir);
    return mainLight;
}

half PerVertexGrazingTerm(VertexOutputBaseSimple i, FragmentCommonData s) {
#if GLOSSMAP
    return saturate(s.smoothness + (1 - s.oneMinusReflectivity));
#else
    return saturate(s.smoothness + i.eyeVec.w);
#endif
}

half PerVertexFresnelTerm(VertexOutputBaseSimple i) { return i.normalWorld.w; }

// The light direction in the space of REFLECTVEC_FOR_SPECULAR.
half3 LightDirForSpecular(VertexOutputBaseSimple i, UnityLight mainLight) {
#if defined(_NORMALMAP)
    return normalize(i.tangentSpaceLightDir);
#else
    return mainLight.dir;
#endif
}

// Diffuse plus a normalised Phong lobe on rl = dot(reflection, light): n = the Blinn-Phong
// exponent of perceptual roughness r = 1 - smoothness (alpha = r^2, n = 2 / alpha^2 - 2, clamped
// to [1e-4, 10000]) and diffColor + specColor (n + 2) / 2 max(rl, 0)^n, i.e. pi times the lobe
// (n + 2) / (2 pi) rl^n, because the diffuse term here is not divided by pi either.
half3 BRDF3DirectSimple(half3 diffColor, half3 specColor, half smoothness, half rl) {
#if SPECULAR_HIGHLIGHTS
    half r = 1 - smoothness;
    half alpha = r * r;
    half n = clamp(2.0 / max(alpha * alpha, 1e-4) - 2.0, 1e-4, 10000.0);
    half specular = (n + 2.0) * 0.5 * pow(max(rl, 0.0), n);
    return diffColor + specular * specColor;
#else
    return diffColor;
#endif
}

half4 fragForwardBaseSimpleInternal(VertexOutputBaseSimple i) {
    FragmentCommonData s = FragmentSetupSimple(i);
    UnityLight mainLight = MainLightSimple(i, s);
#if defined(_NORMALMAP)
    half ndotl = saturate(dot(NormalInTangentSpace(i.tex), normalize(i.tangentSpaceLightDir)));
#else
    half ndotl = mainLight.ndotl;
#endif
    UNITY_LIGHT_ATTENUATION(atten, i, s.posWorld);
    half occlusion = Occlusion(i.tex.xy);
    half rl = dot(REFLECTVEC_FOR_SPECULAR(i, s), LightDirForSpecular(i, mainLight));
    UnityGI gi = FragmentGI(s, occlusion, i.ambientOrLightmapUV, atten, mainLight);
    // Indirect: diffuse GI, and the environment towards the grazing colour at the vertex Fresnel.
    half3 c = s.diffColor * gi.indirect.diffuse +
              gi.indirect.specular * lerp(s.specColor, PerVertexGrazingTerm(i, s), PerVertexFresnelTerm(i));
    c += BRDF3DirectSimple(s.diffColor, s.specColor, s.smoothness, rl) * gi.light.color * ndotl;
    c += Emission(i.tex.xy);
    UNITY_APPLY_FOG(i.fogCoord, c);
    return OutputForward(half4(c, 1), s.alpha);
}
half4 fragForwardBaseSimple(VertexOutputBaseSimple i) : SV_Target { return fragForwardBaseSimpleInternal(i); }

// ---------------------------------------------------------------------------------------------
// Forward add: one light per draw; lightDir is in tangent space with a normal map.
// ---------------------------------------------------------------------------------------------
struct VertexOutputForwardAddSimple {
    UNITY_POSITION(pos);
    float4 tex : TEXCOORD0;
    float3 posWorld : TEXCOORD1;
#if !defined(_NORMALMAP) && SPECULAR_HIGHLIGHTS
    UNITY_FOG_COORDS_PACKED(2, half4)      // yzw: reflection vector
#else
    UNITY_FOG_COORDS_PACKED(2, half1)
#endif
    half3 lightDir : TEXCOORD3;
#if defined(_NORMALMAP)
    #if SPECULAR_HIGHLIGHTS
    half3 tangentSpaceEyeVec : TEXCOORD4;
    #endif
#else
    half3 normalWorld : TEXCOORD4;
#endif
    UNITY_LIGHTING_COORDS(5, 6)
    UNITY_VERTEX_OUTPUT_STEREO
};

VertexOutputForwardAddSimple vertForwardAddSimple(VertexInput v) {
    UNITY_SETUP_INSTANCE_ID(v);
    VertexOutputForwardAddSimple o;
    UNITY_INITIALIZE_OUTPUT(VertexOutputForwardAddSimple, o);
    UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);
    float4 posWorld = mul(unity_ObjectToWorld, v.vertex);
    o.pos = UnityObjectToClipPos(v.vertex);
    o.tex = TexCoords(v);
    o.posWorld = posWorld.xyz;
    UNITY_TRANSFER_LIGHTING(o, v.uv1);
    // Towards the light: the direction for w = 0 (directional), from the vertex for w = 1.
    half3 lightDir = normalize(_WorldSpaceLightPos0.xyz - posWorld.xyz * _WorldSpaceLightPos0.w);
    half3 eyeVec = normalize(posWorld.xyz - _WorldSpaceCameraPos);
    half3 normalWorld = UnityObjectToWorldNormal(v.normal);
#ifdef _NORMALMAP
    half3 tangentSpaceEyeVec;
    TangentSpaceLightingInput(normalWorld, v.tangent, lightDir, eyeVec, o.lightDir, tangentSpaceEyeVec);
    #if SPECULAR_HIGHLIGHTS
    o.tangentSpaceEyeVec = tangentSpaceEyeVec;
    #endif
#else
    o.lightDir = lightDir;
    o.normalWorld = normalWorld;
#endif
    UNITY_TRANSFER_FOG(o, o.pos);
#if !defined(_NORMALMAP) && SPECULAR_HIGHLIGHTS
    o.fogCoord.yzw = reflect(eyeVec, normalWorld);
#endif
    return o;
}

// Surface data of the add pass; s.normalWorld is the interpolated normal without a normal map
// (with one, lighting uses LightSpaceNormal in tangent space and s.normalWorld stays 0).
FragmentCommonData FragmentSetupSimpleAdd(VertexOutputForwardAddSimple i) {
    half alpha = Alpha(i.tex.xy);
#if defined(_ALPHATEST_ON)
    clip(alpha - _Cutoff);
#endif
    FragmentCommonData s = UNITY_SETUP_BRDF_INPUT(i.tex);
#ifndef _NORMALMAP
    s.normalWorld = normalize(i.normalWorld);
#endif
    s.eyeVec = normalize(i.posWorld - _WorldSpaceCameraPos);
    s.posWorld = i.posWorld;
    s.diffColor = PreMultiplyAlpha(s.diffColor, alpha, s.oneMinusReflectivity, s.alpha);
    return s;
}

// The normal in the space of i.lightDir: the normal map's (tangent space) or the world normal.
half3 LightSpaceNormal(VertexOutputForwardAddSimple i, FragmentCommonData s) {
#ifdef _NORMALMAP
    return NormalInTangentSpace(i.tex);
#else
    return s.normalWorld;
#endif
}

half4 fragForwardAddSimpleInternal(VertexOutputForwardAddSimple i) {
    FragmentCommonData s = FragmentSetupSimpleAdd(i);
    UNITY_LIGHT_ATTENUATION(atten, i, s.posWorld);
    half3 lightDir = normalize(i.lightDir);
    half rl = dot(REFLECTVEC_FOR_SPECULAR(i, s), lightDir);
    half3 c = BRDF3DirectSimple(s.diffColor, s.specColor, s.smoothness, rl);
    c *= _LightColor0.rgb * atten * saturate(dot(LightSpaceNormal(i, s), lightDir));
    UNITY_APPLY_FOG(i.fogCoord, c); // towards black in ForwardAdd
    return OutputForward(half4(c, 1), s.alpha);
}
half4 fragForwardAddSimple(VertexOutputForwardAddSimple i) : SV_Target { return fragForwardAddSimpleInternal(i); }

#endif // UNITY_STANDARD_CORE_FORWARD_SIMPLE_INCLUDED
