// SPDX-License-Identifier: Apache-2.0
// varc built-in: TerrainSplatmapCommon.cginc. Surface-shader pieces of the terrain shaders: the
// vertex function (instanced terrain patches read the heightmap), the mix of four splat layers
// by the control texture (with optional normal maps), and the final colour, G-buffer and
// prepass hooks that weight an add pass by the layers' total weight. Written for varc from the
// documented behaviour; not derived from Unity.
#ifndef TERRAIN_SPLATMAP_COMMON_CGINC_INCLUDED
#define TERRAIN_SPLATMAP_COMMON_CGINC_INCLUDED

#include "UnityCG.cginc"

// _NORMALMAP and _TERRAIN_NORMAL_MAP are two names of one switch.
#if defined(_NORMALMAP) && !defined(_TERRAIN_NORMAL_MAP)
    #define _TERRAIN_NORMAL_MAP
#elif !defined(_NORMALMAP) && defined(_TERRAIN_NORMAL_MAP)
    #define _NORMALMAP
#endif

struct Input {
    float4 tc;                 // xy: terrain uv (0..1), zw: control-texture uv
#ifndef TERRAIN_BASE_PASS
    UNITY_FOG_COORDS(0)
#endif
};

sampler2D _Control;
float4 _Control_ST;
float4 _Control_TexelSize;
sampler2D _Splat0, _Splat1, _Splat2, _Splat3;
float4 _Splat0_ST, _Splat1_ST, _Splat2_ST, _Splat3_ST;
#if defined(TERRAIN_BASE_PASS) && defined(UNITY_PASS_META)
float4 _MainTex_ST;
#endif
#ifdef _NORMALMAP
sampler2D _Normal0, _Normal1, _Normal2, _Normal3;
float _NormalScale0, _NormalScale1, _NormalScale2, _NormalScale3;
#endif
#if defined(_ALPHATEST_ON)
sampler2D _TerrainHolesTexture;
// Discards the pixel where the holes texture's red channel is 0 (a hole).
void ClipHoles(float2 uv) {
    float hole = tex2D(_TerrainHolesTexture, uv).r;
    clip(hole == 0.0f ? -1 : 1);
}
#endif

// Instanced terrain: each instance is a patch of a regular grid; _TerrainPatchInstanceData =
// (patch x, patch z, scale, 0) in heightmap samples, _TerrainHeightmapRecipSize =
// (1 / width, 1 / height, 1 / (width - 1), 1 / (height - 1)), _TerrainHeightmapScale = the
// terrain's size per sample (x, z) and its height (y). Heights are packed (UnpackHeightmap), the
// normal map holds rgb = n * 0.5 + 0.5.
// Unity 2021.3+ samples the terrain's normal map in the vertex stage with its own sampler
// states on APIs with separate samplers (all but GL); varc's compiler pairs textures with their
// own samplers, so these are declared for programs that name them.
#if !(defined(SHADER_API_GLCORE) || defined(SHADER_API_GLES3) || defined(SHADER_API_GLES))
#define TERRAIN_USE_SEPARATE_VERTEX_SAMPLER
#endif
#if defined(TERRAIN_USE_SEPARATE_VERTEX_SAMPLER)
SamplerState sampler__TerrainNormalmapTexture;
SamplerState vertex_linear_clamp_sampler;
#endif
#if defined(UNITY_INSTANCING_ENABLED)
sampler2D _TerrainHeightmapTexture;
sampler2D _TerrainNormalmapTexture;
float4 _TerrainHeightmapRecipSize;
float4 _TerrainHeightmapScale;
#endif
UNITY_INSTANCING_BUFFER_START(Terrain)
    UNITY_DEFINE_INSTANCED_PROP(float4, _TerrainPatchInstanceData)
UNITY_INSTANCING_BUFFER_END(Terrain)

#ifndef TERRAIN_SURFACE_OUTPUT
    #define TERRAIN_SURFACE_OUTPUT SurfaceOutput
#endif

// Vertex function (`vertex:SplatmapVert`): places instanced patch vertices from the heightmap,
// gives terrain tangents (along +x), and fills Input: tc.xy the terrain uv, tc.zw the control uv,
// the fog coordinate.
void SplatmapVert(inout appdata_full v, out Input data) {
    UNITY_INITIALIZE_OUTPUT(Input, data);
#if defined(UNITY_INSTANCING_ENABLED)
    float4 patch = UNITY_ACCESS_INSTANCED_PROP(Terrain, _TerrainPatchInstanceData);
    float2 sampleCoords = (v.vertex.xy + patch.xy) * patch.z;
    float4 lookup = float4(sampleCoords * _TerrainHeightmapRecipSize.zw, 0, 0);
    float height = UnpackHeightmap(tex2Dlod(_TerrainHeightmapTexture, lookup));
    v.vertex.xz = sampleCoords * _TerrainHeightmapScale.xz;
    v.vertex.y = height * _TerrainHeightmapScale.y;
    v.vertex.w = 1.0;
    v.normal = tex2Dlod(_TerrainNormalmapTexture, lookup).rgb * 2.0 - 1.0;
    v.texcoord = float4(lookup.xy, 0, 0);
#endif
    v.tangent.xyz = cross(v.normal, float3(0, 0, 1));
    v.tangent.w = -1;
    data.tc.xy = v.texcoord.xy;
    data.tc.zw = TRANSFORM_TEX(v.texcoord.xy, _Control);
#ifndef TERRAIN_BASE_PASS
    UNITY_TRANSFER_FOG(data, UnityObjectToClipPos(v.vertex));
#endif
}

// The control texel at uv, each layer's weight in one channel; weight = their sum (an add pass
// draws nothing where it is 0), splat_control normalised by it. mixedDiffuse = the weighted sum of
// the layers (uv = tc.xy through each layer's _SplatN_ST); with TERRAIN_STANDARD_SHADER each
// layer's alpha is replaced by defaultAlpha's channel (its smoothness) where the layer's texture
// has none. mixedNormal (with _NORMALMAP) = the weighted sum of the layers' normals.
void VarcSplatmapMix(Input IN, half4 defaultAlpha, bool useDefaultAlpha, out half4 splat_control,
                     out half weight, out fixed4 mixedDiffuse, inout fixed3 mixedNormal) {
    float2 controlUV = IN.tc.zw;
    splat_control = tex2D(_Control, controlUV);
    weight = dot(splat_control, half4(1, 1, 1, 1));
#if !defined(SHADER_API_MOBILE) && defined(TERRAIN_SPLAT_ADDPASS)
    clip(weight == 0.0f ? -1 : 1);
#endif
    splat_control /= (weight + 1e-3f);
    float2 uv0 = TRANSFORM_TEX(IN.tc.xy, _Splat0);
    float2 uv1 = TRANSFORM_TEX(IN.tc.xy, _Splat1);
    float2 uv2 = TRANSFORM_TEX(IN.tc.xy, _Splat2);
    float2 uv3 = TRANSFORM_TEX(IN.tc.xy, _Splat3);
    half4 alpha = useDefaultAlpha ? defaultAlpha : half4(1, 1, 1, 1);
    mixedDiffuse = 0.0f;
    mixedDiffuse += splat_control.r * tex2D(_Splat0, uv0) * half4(1, 1, 1, alpha.r);
    mixedDiffuse += splat_control.g * tex2D(_Splat1, uv1) * half4(1, 1, 1, alpha.g);
    mixedDiffuse += splat_control.b * tex2D(_Splat2, uv2) * half4(1, 1, 1, alpha.b);
    mixedDiffuse += splat_control.a * tex2D(_Splat3, uv3) * half4(1, 1, 1, alpha.a);
#ifdef _NORMALMAP
    mixedNormal  = UnpackNormalWithScale(tex2D(_Normal0, uv0), _NormalScale0) * splat_control.r;
    mixedNormal += UnpackNormalWithScale(tex2D(_Normal1, uv1), _NormalScale1) * splat_control.g;
    mixedNormal += UnpackNormalWithScale(tex2D(_Normal2, uv2), _NormalScale2) * splat_control.b;
    mixedNormal += UnpackNormalWithScale(tex2D(_Normal3, uv3), _NormalScale3) * splat_control.a;
    mixedNormal.z += 1e-5f;  // never a zero vector
#endif
}

#ifdef TERRAIN_STANDARD_SHADER
void SplatmapMix(Input IN, half4 defaultAlpha, out half4 splat_control, out half weight, out fixed4 mixedDiffuse, inout fixed3 mixedNormal) {
    VarcSplatmapMix(IN, defaultAlpha, true, splat_control, weight, mixedDiffuse, mixedNormal);
}
#else
void SplatmapMix(Input IN, out half4 splat_control, out half weight, out fixed4 mixedDiffuse, inout fixed3 mixedNormal) {
    VarcSplatmapMix(IN, half4(1, 1, 1, 1), false, splat_control, weight, mixedDiffuse, mixedNormal);
}
#endif

#ifndef TERRAIN_BASE_PASS
// Final hooks: an add pass's result is weighted by the layers' weight (o.Alpha) so that passes
// add up; fog is applied with black in add passes.
void SplatmapFinalColor(Input IN, TERRAIN_SURFACE_OUTPUT o, inout fixed4 color) {
    color *= o.Alpha;
#ifdef TERRAIN_SPLAT_ADDPASS
    UNITY_APPLY_FOG_COLOR(IN.fogCoord, color, fixed4(0, 0, 0, 0));
#else
    UNITY_APPLY_FOG(IN.fogCoord, color);
#endif
}
void SplatmapFinalPrepass(Input IN, TERRAIN_SURFACE_OUTPUT o, inout fixed4 normalSpec) {
    normalSpec *= o.Alpha;
}
void SplatmapFinalGBuffer(Input IN, TERRAIN_SURFACE_OUTPUT o, inout half4 outGBuffer0, inout half4 outGBuffer1, inout half4 outGBuffer2, inout half4 emission) {
    outGBuffer0 *= o.Alpha;
    outGBuffer1 *= o.Alpha;
    outGBuffer2 *= o.Alpha;
    emission *= o.Alpha;
}
#endif

#endif // TERRAIN_SPLATMAP_COMMON_CGINC_INCLUDED
