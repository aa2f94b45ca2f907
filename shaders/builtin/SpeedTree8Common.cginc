// SPDX-License-Identifier: Apache-2.0
// varc built-in: SpeedTree8Common.cginc. SpeedTree 8 trees as Standard surface shaders: the
// vertex function SpeedTreeVert (LOD blend, leaf facing, wind chosen by the _WINDQUALITY_*
// keywords), the surface function SpeedTreeSurf and the SpeedTreeSubsurface lighting model (the
// Standard model plus light through leaves, EFFECT_SUBSURFACE). Written for varc from the
// documented behaviour; not derived from Unity or SpeedTree.
//
// Vertex layout (appdata_full; object space, Y up, the tree's base at 0): as SpeedTreeVertex.cginc
// (texcoord.zw branch wind, texcoord1 next-LOD position and leaf wind scale, texcoord2 leaf anchor
// and packed growth direction, texcoord3.xy packed ripple direction and leaf group), plus
// texcoord3.w the vertex's geometry type (GEOM_TYPE_BRANCH .. GEOM_TYPE_FACINGLEAF); color.r
// ambient occlusion.
#ifndef SPEEDTREE8_COMMON_INCLUDED
#define SPEEDTREE8_COMMON_INCLUDED

#include "UnityCG.cginc"
#include "UnityPBSLighting.cginc"

// The geometry types of texcoord3.w.
#define GEOM_TYPE_BRANCH 0
#define GEOM_TYPE_FROND 1
#define GEOM_TYPE_LEAF 2
#define GEOM_TYPE_FACINGLEAF 3

#if defined(ENABLE_WIND) && !defined(_WINDQUALITY_NONE)
#define SPEEDTREE_Y_UP
#include "SpeedTreeWind.cginc"
float _WindEnabled;     // 0 turns the wind off for this renderer
float _GlobalWindTime;  // seconds, added to the phases of the _ST_Wind* times
#endif

sampler2D _MainTex;
fixed4 _Color;
int _TwoSided;  // the material renders both faces (its Cull state); the back faces' normals
                // are flipped with EFFECT_BACKSIDE_NORMALS

#ifdef EFFECT_BUMP
sampler2D _BumpMap;
#endif
#ifdef EFFECT_EXTRA_TEX
sampler2D _ExtraTex;  // r smoothness, g metallic, b occlusion
#else
half _Glossiness;
half _Metallic;
#endif
#ifdef EFFECT_HUE_VARIATION
half4 _HueVariationColor;  // rgb the colour trees shift towards, a the largest shift (0..1)
#endif
#ifdef EFFECT_BILLBOARD
half _BillboardShadowFade;  // the share of a billboard's shadow (shadow caster alpha scale)
#endif
#ifdef EFFECT_SUBSURFACE
sampler2D _SubsurfaceTex;
fixed4 _SubsurfaceColor;
half _SubsurfaceIndirect;  // the share of indirect light that passes through the leaf
#endif

// color: _Color with the vertex's ambient occlusion in rgb and the hue variation amount in a.
// facing: Unity declares it `: VFACE` for its surface generator to fill. glslang's HLSL front end
// drops members with a built-in semantic from a struct (reading IN.facing would not compile),
// and varc's surface passes fill no VFACE member, so it is a plain member left at 0, which
// reads as a front face.
struct Input {
    half2 uv_MainTex : TEXCOORD0;
    fixed4 color : COLOR;
#ifdef EFFECT_BACKSIDE_NORMALS
    fixed facing;
#endif
};

// Turns a leaf card to the camera: the offset of |vPos| from |anchor| is read as (right, up,
// towards the camera) and laid along the camera's axes in object space.
float3 DoLeafFacing(float3 vPos, float3 anchor) {
    float3x3 toObject = (float3x3)unity_WorldToObject;
    float3 offset = vPos - anchor;
    return anchor + normalize(mul(toObject, UNITY_MATRIX_V[0].xyz)) * offset.x +
           normalize(mul(toObject, UNITY_MATRIX_V[1].xyz)) * offset.y +
           normalize(mul(toObject, UNITY_MATRIX_V[2].xyz)) * offset.z;
}

#if defined(ENABLE_WIND) && !defined(_WINDQUALITY_NONE)
// The wind of the _WINDQUALITY_* keyword (none of them: fast): every vertex bends with the
// tree; branches sway (better, best, palm); leaves ripple and, with best and palm, tumble;
// fronds ripple (palm). Times are the uniforms' plus _GlobalWindTime.
float3 VarcSpeedTree8Wind(inout appdata_full data, float3 position, int geometryType) {
    float3 wind = mul((float3x3)unity_WorldToObject, _ST_WindVector.xyz);
    float3 anchor = mul((float3x3)unity_WorldToObject, _ST_WindBranchAnchor.xyz) * _ST_WindBranchAnchor.w;
    float3 instance = unity_ObjectToWorld._m03_m13_m23;
    float3 normal = data.normal;
#if defined(_WINDQUALITY_PALM)
    bool palm = true, best = true;
#elif defined(_WINDQUALITY_BEST)
    bool palm = false, best = true;
#else
    bool palm = false, best = false;
#endif
#if defined(_WINDQUALITY_PALM)
    if (geometryType == GEOM_TYPE_FROND) {
        float3 binormal = cross(data.normal, data.tangent.xyz) * data.tangent.w;
        position = RippleFrond(position, normal, data.texcoord.x, data.texcoord.y,
                               data.texcoord3.x, data.texcoord1.w, data.texcoord1.w, binormal,
                               data.tangent.xyz);
    }
#endif
    if (geometryType >= GEOM_TYPE_LEAF) {
        position = LeafWind(best, data.texcoord3.y > 0.5, position, normal, data.texcoord1.w,
                            data.texcoord2.xyz, data.texcoord2.w, data.texcoord3.x,
                            _GlobalWindTime + dot(data.texcoord2.xyz, float3(1.0, 1.0, 1.0)), wind);
    }
#if defined(_WINDQUALITY_BETTER) || defined(_WINDQUALITY_BEST) || defined(_WINDQUALITY_PALM)
    position = BranchWind(palm, position, instance,
                          float4(data.texcoord.zw + float2(0.0, _GlobalWindTime), 0.0, 0.0), wind,
                          anchor);
#endif
    data.normal = normal;
    return GlobalWind(position, instance, true, wind, _ST_WindGlobal.x + _GlobalWindTime);
}
#endif

// Moves |data| for LOD |lodValue|: with LOD_FADE_PERCENTAGE the position blends to the next
// LOD's (texcoord1.xyz) by lodValue; facing leaves turn to the camera; then the wind, unless
// _WindEnabled is 0. Billboards (EFFECT_BILLBOARD) only bend with the whole tree.
void OffsetSpeedTreeVertex(inout appdata_full data, float lodValue) {
    float3 position = data.vertex.xyz;
    int geometryType = (int)(data.texcoord3.w + 0.25);
#ifdef LOD_FADE_PERCENTAGE
    position = lerp(position, data.texcoord1.xyz, lodValue);
#endif
    if (geometryType == GEOM_TYPE_FACINGLEAF) position = DoLeafFacing(position, data.texcoord2.xyz);
#if defined(ENABLE_WIND) && !defined(_WINDQUALITY_NONE)
    if (_WindEnabled > 0.0) {
#ifdef EFFECT_BILLBOARD
        float3 wind = mul((float3x3)unity_WorldToObject, _ST_WindVector.xyz);
        position = GlobalWind(position, unity_ObjectToWorld._m03_m13_m23, true, wind,
                              _ST_WindGlobal.x + _GlobalWindTime);
#else
        position = VarcSpeedTree8Wind(data, position, geometryType);
#endif
    }
#endif
    data.vertex.xyz = position;
}

// The vertex function of `#pragma surface SpeedTreeSurf ... vertex:SpeedTreeVert`: the offset
// with unity_LODFade.x, and the vertex colour (_Color, occlusion, hue variation amount).
void SpeedTreeVert(inout appdata_full v) {
    UNITY_SETUP_INSTANCE_ID(v);
    float occlusion = v.color.r;
    OffsetSpeedTreeVertex(v, unity_LODFade.x);
    v.color = half4(_Color.rgb * occlusion, 0.0);
#ifdef EFFECT_HUE_VARIATION
    float3 base = unity_ObjectToWorld._m03_m13_m23;
    v.color.a = saturate(frac(dot(base, float3(1.0, 1.0, 1.0))) * _HueVariationColor.a);
#endif
}

// Light through a leaf (EFFECT_SUBSURFACE): SpeedTreeSurf leaves the leaf's subsurface colour
// here for the lighting functions of the same pixel (SurfaceOutputStandard has no member for it).
static half3 varcSpeedTreeSubsurface = half3(0.0, 0.0, 0.0);

// The Standard surface of a SpeedTree 8 pixel: diffuse texture times the vertex colour, cut out
// below alpha 1/3 (SpeedTree 8 materials have no cutoff property), hue shift, normal map (flipped
// on back faces with EFFECT_BACKSIDE_NORMALS), smoothness / metallic / occlusion from _ExtraTex
// or the material, and the subsurface colour.
void SpeedTreeSurf(Input IN, inout SurfaceOutputStandard OUT) {
    half4 diffuse = tex2D(_MainTex, IN.uv_MainTex);
    OUT.Alpha = diffuse.a * _Color.a;
#if defined(EFFECT_BILLBOARD) && defined(UNITY_PASS_SHADOWCASTER)
    OUT.Alpha *= _BillboardShadowFade;
#endif
    clip(OUT.Alpha - 0.3333);
#ifdef EFFECT_HUE_VARIATION
    half3 shifted = lerp(diffuse.rgb, _HueVariationColor.rgb, IN.color.a);
    half before = max(diffuse.r, max(diffuse.g, diffuse.b));
    half after = max(shifted.r, max(shifted.g, shifted.b));
    diffuse.rgb = saturate(shifted * (before / max(after, 1e-4)));
#endif
    OUT.Albedo = diffuse.rgb * IN.color.rgb;
#ifdef EFFECT_BUMP
    OUT.Normal = UnpackNormal(tex2D(_BumpMap, IN.uv_MainTex));
#ifdef EFFECT_BACKSIDE_NORMALS
    if (IN.facing < 0.0) OUT.Normal.z = -OUT.Normal.z;
#endif
#endif
#ifdef EFFECT_EXTRA_TEX
    half4 extra = tex2D(_ExtraTex, IN.uv_MainTex);
    OUT.Smoothness = extra.r;
    OUT.Metallic = extra.g;
    OUT.Occlusion = extra.b;
#else
    OUT.Smoothness = _Glossiness;
    OUT.Metallic = _Metallic;
#endif
#ifdef EFFECT_SUBSURFACE
    varcSpeedTreeSubsurface = tex2D(_SubsurfaceTex, IN.uv_MainTex).rgb * _SubsurfaceColor.rgb;
#endif
}

// The Standard model plus, with EFFECT_SUBSURFACE, the light passing through the leaf towards
// the viewer: subsurface * (light colour * saturate(V . -L)^2 + _SubsurfaceIndirect * indirect
// diffuse), reduced by metalness.
half4 LightingSpeedTreeSubsurface(inout SurfaceOutputStandard s, half3 viewDir, UnityGI gi) {
    half4 color = LightingStandard(s, viewDir, gi);
#ifdef EFFECT_SUBSURFACE
    half through = saturate(dot(viewDir, -gi.light.dir));
    half3 light = gi.light.color * (through * through) + gi.indirect.diffuse * _SubsurfaceIndirect;
    color.rgb += varcSpeedTreeSubsurface * light * (1.0 - s.Metallic);
#endif
    return color;
}

// The deferred form: the Standard G-buffer, and the indirect light through the leaf added to
// the emission (the direct part needs the light, which a G-buffer pass does not have).
half4 LightingSpeedTreeSubsurface_Deferred(SurfaceOutputStandard s, half3 viewDir, UnityGI gi,
                                           out half4 outGBuffer0, out half4 outGBuffer1,
                                           out half4 outGBuffer2) {
    half4 emission = LightingStandard_Deferred(s, viewDir, gi, outGBuffer0, outGBuffer1, outGBuffer2);
#ifdef EFFECT_SUBSURFACE
    emission.rgb += varcSpeedTreeSubsurface * gi.indirect.diffuse * _SubsurfaceIndirect * (1.0 - s.Metallic);
#endif
    return emission;
}

// Global illumination as the Standard model's.
void LightingSpeedTreeSubsurface_GI(inout SurfaceOutputStandard s, UnityGIInput data, inout UnityGI gi) {
    LightingStandard_GI(s, data, gi);
}

#endif // SPEEDTREE8_COMMON_INCLUDED
