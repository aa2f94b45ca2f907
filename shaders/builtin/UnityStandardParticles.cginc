// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityStandardParticles.cginc. Programs of the Standard particle shaders
// (Particles/Standard Surface and Particles/Standard Unlit): albedo texture with optional
// flip-book blending (_REQUIRE_UV2), the colour modes that combine the particle colour with the
// albedo (multiply, additive/subtractive/difference, overlay, colour), soft particles
// (SOFTPARTICLES_ON), near-camera fading (_FADING_ON), refraction through a grab pass
// (EFFECT_BUMP), emission, normal maps and metallic/smoothness. Written for varc from the
// documented behaviour (Unity manual, "Standard Particle Shaders"); not derived from Unity.
#ifndef UNITY_STANDARD_PARTICLES_INCLUDED
#define UNITY_STANDARD_PARTICLES_INCLUDED

#if _REQUIRE_UV2
#define _FLIPBOOK_BLENDING 1
#endif
#if EFFECT_BUMP
#define _DISTORTION_ON 1
#endif
#if defined(SOFTPARTICLES_ON) && !defined(_FADING_ON)
#define _FADING_ON 1
#endif

#include "HLSLSupport.cginc"
#include "UnityPBSLighting.cginc"
#include "UnityStandardParticleInstancing.cginc"

// Material values.
sampler2D _MainTex;
float4 _MainTex_ST;
half4 _Color;
sampler2D _BumpMap;
half _BumpScale;
sampler2D _EmissionMap;
half3 _EmissionColor;
sampler2D _MetallicGlossMap;
half _Metallic;
half _Glossiness;
UNITY_DECLARE_DEPTH_TEXTURE(_CameraDepthTexture);
float4 _SoftParticleFadeParams;   // x: near fade distance, y: 1 / fade range
float4 _CameraFadeParams;         // x: near fade distance, y: 1 / fade range
half _Cutoff;
int _DstBlend;
#if _DISTORTION_ON
sampler2D _GrabTexture;
half _DistortionStrengthScaled;
half _DistortionBlend;
#endif
#if defined(_COLORADDSUBDIFF_ON)
half4 _ColorAddSubDiff;           // x: 1 add, -1 subtract; y: 1 for the absolute difference
#endif

#define SOFT_PARTICLE_NEAR_FADE _SoftParticleFadeParams.x
#define SOFT_PARTICLE_INV_FADE_DISTANCE _SoftParticleFadeParams.y
#define CAMERA_NEAR_FADE _CameraFadeParams.x
#define CAMERA_INV_FADE_DISTANCE _CameraFadeParams.y
#define SampleGrabPassTexture(tex, t) tex2Dproj(tex, t)

// Premultiplied-alpha blending multiplies the albedo's rgb by its alpha.
#if defined(_ALPHAPREMULTIPLY_ON)
#define ALBEDO_MUL albedo
#else
#define ALBEDO_MUL albedo.a
#endif

struct appdata_particles {
    float4 vertex : POSITION;
    float3 normal : NORMAL;
    fixed4 color : COLOR;
#if defined(_FLIPBOOK_BLENDING) && !defined(UNITY_PARTICLE_INSTANCING_ENABLED)
    float4 texcoords : TEXCOORD0;      // xy: frame, zw: next frame
    float texcoordBlend : TEXCOORD1;   // blend towards the next frame
#else
    float2 texcoords : TEXCOORD0;
#endif
#if defined(_NORMALMAP)
    float4 tangent : TANGENT;
#endif
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

struct Input {
    float4 color : COLOR;
    float2 texcoord;
#if defined(_FLIPBOOK_BLENDING)
    float3 texcoord2AndBlend;
#endif
#if defined(SOFTPARTICLES_ON) || defined(_FADING_ON)
    float4 projectedPosition;          // xy/w: screen uv, z: eye depth
#endif
#if _DISTORTION_ON
    float4 grabPassPosition;
#endif
};

struct VertexOutput {
    float4 vertex : SV_POSITION;
    float4 color : COLOR;
    UNITY_FOG_COORDS(0)
    float2 texcoord : TEXCOORD1;
#if defined(_FLIPBOOK_BLENDING)
    float3 texcoord2AndBlend : TEXCOORD2;
#endif
#if defined(SOFTPARTICLES_ON) || defined(_FADING_ON)
    float4 projectedPosition : TEXCOORD3;
#endif
#if _DISTORTION_ON
    float4 grabPassPosition : TEXCOORD4;
#endif
    UNITY_VERTEX_OUTPUT_STEREO
};

// RGB <-> HSV (hue, saturation, value in [0, 1]) for the colour mode "Color".
#if defined(_COLORCOLOR_ON)
half3 RGBtoHSV(half3 arg1) {
    half maxValue = max(arg1.r, max(arg1.g, arg1.b));
    half minValue = min(arg1.r, min(arg1.g, arg1.b));
    half range = maxValue - minValue;
    half hue = 0;
    if (range > 1e-6) {
        if (maxValue == arg1.r) hue = (arg1.g - arg1.b) / range;
        else if (maxValue == arg1.g) hue = 2.0 + (arg1.b - arg1.r) / range;
        else hue = 4.0 + (arg1.r - arg1.g) / range;
        hue = frac(hue / 6.0 + 1.0);
    }
    half saturation = maxValue > 1e-6 ? range / maxValue : 0;
    return half3(hue, saturation, maxValue);
}
half3 HSVtoRGB(half3 arg1) {
    half3 rgb = saturate(abs(frac(arg1.x + half3(1.0, 2.0 / 3.0, 1.0 / 3.0)) * 6.0 - 3.0) - 1.0);
    return arg1.z * lerp(half3(1, 1, 1), rgb, arg1.y);
}
#endif

// Vertex colour: the particle system's colour (from the instance with procedural instancing).
#if defined(UNITY_PARTICLE_INSTANCING_ENABLED)
#define vertColor(c) vertInstancingColor(c);
#else
#define vertColor(c)
#endif

// Texture coordinates through _MainTex_ST; with flip-book blending also the next frame and the
// blend factor.
#if defined(_FLIPBOOK_BLENDING)
#if defined(UNITY_PARTICLE_INSTANCING_ENABLED)
#define vertTexcoord(v, o) \
    vertInstancingUVs(v.texcoords.xy, o.texcoord, o.texcoord2AndBlend); \
    o.texcoord = TRANSFORM_TEX(o.texcoord, _MainTex); \
    o.texcoord2AndBlend.xy = TRANSFORM_TEX(o.texcoord2AndBlend.xy, _MainTex);
#else
#define vertTexcoord(v, o) \
    o.texcoord = TRANSFORM_TEX(v.texcoords.xy, _MainTex); \
    o.texcoord2AndBlend.xy = TRANSFORM_TEX(v.texcoords.zw, _MainTex); \
    o.texcoord2AndBlend.z = v.texcoordBlend;
#endif
#else
#define vertTexcoord(v, o) \
    vertInstancingUVs(v.texcoords.xy, o.texcoord); \
    o.texcoord = TRANSFORM_TEX(o.texcoord, _MainTex);
#endif

// Soft particles and camera fading need the screen position and eye depth of the particle.
#if defined(SOFTPARTICLES_ON) || defined(_FADING_ON)
#define vertFading(o) \
    o.projectedPosition = ComputeScreenPos(clipPosition); \
    COMPUTE_EYEDEPTH(o.projectedPosition.z);
#else
#define vertFading(o)
#endif

#if _DISTORTION_ON
#define vertDistortion(o) o.grabPassPosition = ComputeGrabScreenPos(clipPosition);
#else
#define vertDistortion(o)
#endif

// The albedo texture, blended between the two flip-book frames.
fixed4 readTexture(sampler2D tex, Input IN) {
    fixed4 color = tex2D(tex, IN.texcoord);
#ifdef _FLIPBOOK_BLENDING
    fixed4 color2 = tex2D(tex, IN.texcoord2AndBlend.xy);
    color = lerp(color, color2, IN.texcoord2AndBlend.z);
#endif
    return color;
}
fixed4 readTexture(sampler2D tex, VertexOutput IN) {
    fixed4 color = tex2D(tex, IN.texcoord);
#ifdef _FLIPBOOK_BLENDING
    fixed4 color2 = tex2D(tex, IN.texcoord2AndBlend.xy);
    color = lerp(color, color2, IN.texcoord2AndBlend.z);
#endif
    return color;
}

// Combines `albedo` with the particle colour i.color:
//   overlay: per channel 2ab where the albedo is below 0.5, else 1 - 2(1-a)(1-b); alpha multiplied
//   color:   the particle colour's hue and saturation with the albedo's value
//   add/sub/difference: albedo + sign * colour (absolute value for difference); alpha multiplied
//   default: multiply
#if defined(_COLOROVERLAY_ON)
#define fragColorMode(i) \
    albedo.rgb = lerp(1 - 2 * (1 - albedo.rgb) * (1 - i.color.rgb), 2 * albedo.rgb * i.color.rgb, step(albedo.rgb, 0.5)); \
    albedo.a *= i.color.a;
#elif defined(_COLORCOLOR_ON)
#define fragColorMode(i) \
    half3 aHSL = RGBtoHSV(albedo.rgb); \
    half3 bHSL = RGBtoHSV(i.color.rgb); \
    half3 rHSL = half3(bHSL.x, bHSL.y, aHSL.z); \
    albedo = fixed4(HSVtoRGB(rHSL), albedo.a * i.color.a);
#elif defined(_COLORADDSUBDIFF_ON)
#define fragColorMode(i) \
    albedo.rgb = albedo.rgb + i.color.rgb * _ColorAddSubDiff.x; \
    albedo.rgb = lerp(albedo.rgb, abs(albedo.rgb), _ColorAddSubDiff.y); \
    albedo.a *= i.color.a;
#else
#define fragColorMode(i) albedo *= i.color;
#endif

// Soft particles: alpha fades with the distance between the particle and the scene behind it,
// saturate((sceneDepth - SOFT_PARTICLE_NEAR_FADE - particleDepth) * SOFT_PARTICLE_INV_FADE_DISTANCE).
#if defined(SOFTPARTICLES_ON) && defined(_FADING_ON)
#define fragSoftParticles(i) \
    if (SOFT_PARTICLE_NEAR_FADE > 0.0 || SOFT_PARTICLE_INV_FADE_DISTANCE > 0.0) { \
        float sceneZ = LinearEyeDepth(SAMPLE_DEPTH_TEXTURE_PROJ(_CameraDepthTexture, UNITY_PROJ_COORD(i.projectedPosition))); \
        float fade = saturate(SOFT_PARTICLE_INV_FADE_DISTANCE * ((sceneZ - SOFT_PARTICLE_NEAR_FADE) - i.projectedPosition.z)); \
        ALBEDO_MUL *= fade; \
    }
#else
#define fragSoftParticles(i)
#endif

// Camera fading: alpha fades in from CAMERA_NEAR_FADE over 1 / CAMERA_INV_FADE_DISTANCE.
#if defined(_FADING_ON)
#define fragCameraFading(i) \
    float cameraFade = saturate((i.projectedPosition.z - CAMERA_NEAR_FADE) * CAMERA_INV_FADE_DISTANCE); \
    ALBEDO_MUL *= cameraFade;
#else
#define fragCameraFading(i)
#endif

// Refraction: the grab pass seen through the normal map, offset by the normal's xy times
// _DistortionStrengthScaled, replaces the albedo's colour by _DistortionBlend.
#if _DISTORTION_ON
#define fragDistortion(i) \
    float4 grabPosUV = UNITY_PROJ_COORD(i.grabPassPosition); \
    grabPosUV.xy += normal.xy * _DistortionStrengthScaled * albedo.a; \
    half3 grabPass = SampleGrabPassTexture(_GrabTexture, grabPosUV).rgb; \
    albedo.rgb = lerp(grabPass, albedo.rgb, saturate(albedo.a - _DistortionBlend));
#else
#define fragDistortion(i)
#endif

// Surface-shader vertex function (`vertex:vert`).
void vert(inout appdata_particles v, out Input o) {
    UNITY_INITIALIZE_OUTPUT(Input, o);
    float4 clipPosition = UnityObjectToClipPos(v.vertex);
    vertColor(v.color);
    vertTexcoord(v, o);
    vertFading(o);
    vertDistortion(o);
    o.color = v.color;
}

// Surface function (Particles/Standard Surface, `surf Standard`): albedo through the colour mode
// and fades, normal map, emission, metallic/smoothness from _MetallicGlossMap.r/.a or the values.
void surf(Input IN, inout SurfaceOutputStandard o) {
    half4 albedo = readTexture(_MainTex, IN);
    albedo *= _Color;
    fragColorMode(IN);
    fragSoftParticles(IN);
    fragCameraFading(IN);
#if defined(_METALLICGLOSSMAP)
    fixed2 metallicGloss = readTexture(_MetallicGlossMap, IN).ra * fixed2(1.0, _Glossiness);
#else
    fixed2 metallicGloss = fixed2(_Metallic, _Glossiness);
#endif
#if defined(_NORMALMAP)
    float3 normal = normalize(UnpackNormalWithScale(readTexture(_BumpMap, IN), _BumpScale));
#else
    float3 normal = float3(0, 0, 1);
#endif
#if defined(_EMISSION)
    half3 emission = readTexture(_EmissionMap, IN).rgb;
#else
    half3 emission = 0;
#endif
    fragDistortion(IN);
    o.Albedo = albedo.rgb;
#if defined(_NORMALMAP)
    o.Normal = normal;
#endif
    o.Emission = emission * _EmissionColor;
    o.Metallic = metallicGloss.r;
    o.Smoothness = metallicGloss.g;
#if defined(_ALPHABLEND_ON) || defined(_ALPHAPREMULTIPLY_ON) || defined(_ALPHAOVERLAY_ON)
    o.Alpha = albedo.a;
#else
    o.Alpha = 1;
#endif
#if defined(_ALPHAMODULATE_ON)
    o.Albedo = lerp(half3(1.0, 1.0, 1.0), albedo.rgb, albedo.a);
#endif
#if defined(_ALPHATEST_ON)
    clip(albedo.a - _Cutoff + 0.0001);
#endif
}

// Unlit programs (Particles/Standard Unlit).
void vertParticleUnlit(appdata_particles v, out VertexOutput o) {
    UNITY_SETUP_INSTANCE_ID(v);
    UNITY_INITIALIZE_OUTPUT(VertexOutput, o);
    float4 clipPosition = UnityObjectToClipPos(v.vertex);
    o.vertex = clipPosition;
    o.color = v.color;
    vertColor(o.color);
    vertTexcoord(v, o);
    vertFading(o);
    vertDistortion(o);
    UNITY_TRANSFER_FOG(o, o.vertex);
}

half4 fragParticleUnlit(VertexOutput IN) : SV_Target {
    half4 albedo = readTexture(_MainTex, IN);
    albedo *= _Color;
    fragColorMode(IN);
    fragSoftParticles(IN);
    fragCameraFading(IN);
#if defined(_NORMALMAP)
    float3 normal = normalize(UnpackNormalWithScale(readTexture(_BumpMap, IN), _BumpScale));
#else
    float3 normal = float3(0, 0, 1);
#endif
#if defined(_EMISSION)
    half3 emission = readTexture(_EmissionMap, IN).rgb * _EmissionColor;
#else
    half3 emission = 0;
#endif
    fragDistortion(IN);
    half4 result = albedo;
#if defined(_ALPHAMODULATE_ON)
    result.rgb = lerp(half3(1.0, 1.0, 1.0), albedo.rgb, albedo.a);
#endif
    result.rgb += emission;
#if !defined(_ALPHABLEND_ON) && !defined(_ALPHAPREMULTIPLY_ON) && !defined(_ALPHAOVERLAY_ON)
    result.a = 1;
#endif
#if defined(_ALPHATEST_ON)
    clip(albedo.a - _Cutoff + 0.0001);
#endif
    UNITY_APPLY_FOG_COLOR(IN.fogCoord, result, fixed4(0, 0, 0, 0));
    return result;
}

#endif // UNITY_STANDARD_PARTICLES_INCLUDED
