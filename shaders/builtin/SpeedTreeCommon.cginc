// SPDX-License-Identifier: Apache-2.0
// varc built-in: SpeedTreeCommon.cginc. The surface-shader side of SpeedTree (7) trees: the
// Input the vertex function SpeedTreeVert fills, and SpeedTreeFrag, which turns it into albedo,
// alpha (alpha-tested for fronds and leaves) and a normal (EFFECT_BUMP), with branch detail and
// hue variation. A shader's surface function copies the result with SPEEDTREE_COPY_FRAG.
// Written for varc from the documented behaviour; not derived from Unity or SpeedTree.
#ifndef SPEEDTREE_COMMON_INCLUDED
#define SPEEDTREE_COMMON_INCLUDED

#include "UnityCG.cginc"

// SpeedTree data is authored Y up (the wind's global bend works on the height in Y).
#define SPEEDTREE_Y_UP

#ifdef GEOM_TYPE_BRANCH_DETAIL
// A branch with a detail texture is a branch.
#ifndef GEOM_TYPE_BRANCH
#define GEOM_TYPE_BRANCH
#endif
#endif

#include "SpeedTreeVertex.cginc"

#if defined(GEOM_TYPE_FROND) || defined(GEOM_TYPE_LEAF) || defined(GEOM_TYPE_FACING_LEAF)
// Fronds and leaves are cut out at alpha _Cutoff.
#ifndef SPEEDTREE_ALPHATEST
#define SPEEDTREE_ALPHATEST
#endif
fixed _Cutoff;
#endif

sampler2D _MainTex;
fixed4 _Color;

#ifdef GEOM_TYPE_BRANCH_DETAIL
sampler2D _DetailTex;
#endif

#ifdef EFFECT_HUE_VARIATION
half4 _HueVariation;  // rgb the colour trees shift towards, a the largest shift (0..1)
#endif

#if defined(EFFECT_BUMP) && !defined(LIGHTMAP_ON)
sampler2D _BumpMap;
// SpeedTreeFragOut has a tangent-space Normal, which the copy hands to the surface output.
#define SPEEDTREE_DATA_NORMAL fixed3 Normal;
#define SPEEDTREE_COPY_NORMAL(to, from) to.Normal = from.Normal;
#else
#define SPEEDTREE_DATA_NORMAL
#define SPEEDTREE_COPY_NORMAL(to, from)
#endif

#define SPEEDTREE_COPY_FRAG(to, from) \
    to.Albedo = from.Albedo;          \
    to.Alpha = from.Alpha;            \
    SPEEDTREE_COPY_NORMAL(to, from)

// What SpeedTreeVert passes to the surface function: color = _Color with the vertex's ambient
// occlusion in rgb; interpolator1 = (diffuse UV, hue variation amount); interpolator2 = (detail
// UV, detail weight) for branches with detail.
struct Input {
    fixed4 color;
    half3 interpolator1;
#ifdef GEOM_TYPE_BRANCH_DETAIL
    half3 interpolator2;
#endif
    UNITY_DITHER_CROSSFADE_COORDS
};

// The names SpeedTree shaders read the interpolators by.
#define mainTexUV interpolator1.xy
#ifdef EFFECT_HUE_VARIATION
#define HueVariationAmount interpolator1.z
#endif
#ifdef GEOM_TYPE_BRANCH_DETAIL
#define Detail interpolator2
#endif

// The share of the hue shift of the tree whose base is at world position |treeBase|, in
// [0, _HueVariation.a): each tree gets its own, a vertex adds a little of its own position so
// that the crown is not one flat colour.
half VarcSpeedTreeHueVariation(float3 treeBase, float3 vertexPos) {
#ifdef EFFECT_HUE_VARIATION
    float seed = frac(dot(treeBase, float3(1.0, 1.0, 1.0)) + 0.1 * dot(vertexPos, float3(1.0, 0.0, 1.0)));
    return saturate(seed * _HueVariation.a);
#else
    return 0.0;
#endif
}

// The vertex function of `#pragma surface ... vertex:SpeedTreeVert`: applies the LOD blend,
// facing and wind (OffsetSpeedTreeVertex with unity_LODFade.x) and fills |OUT|.
void SpeedTreeVert(inout SpeedTreeVB IN, out Input OUT) {
    UNITY_SETUP_INSTANCE_ID(IN);
    UNITY_INITIALIZE_OUTPUT(Input, OUT);
    OUT.mainTexUV = IN.texcoord.xy;
    OUT.color = _Color;
    OUT.color.rgb *= IN.color.r;
    OUT.interpolator1.z = VarcSpeedTreeHueVariation(unity_ObjectToWorld._m03_m13_m23, IN.vertex.xyz);
#ifdef GEOM_TYPE_BRANCH_DETAIL
    OUT.interpolator2 = IN.texcoord2.xyz;
#endif
    OffsetSpeedTreeVertex(IN, unity_LODFade.x);
    IN.color = OUT.color;  // the vertex colour a surface shader's Input.color interpolates
    UNITY_TRANSFER_DITHER_CROSSFADE(OUT, IN.vertex)
}

// |color| shifted towards _HueVariation.rgb by |amount|, at the brightness (largest channel) of
// the original.
half3 VarcSpeedTreeShiftHue(half3 color, half amount) {
#ifdef EFFECT_HUE_VARIATION
    half3 shifted = lerp(color, _HueVariation.rgb, amount);
    half before = max(color.r, max(color.g, color.b));
    half after = max(shifted.r, max(shifted.g, shifted.b));
    return saturate(shifted * (before / max(after, 1e-4)));
#else
    return color;
#endif
}

struct SpeedTreeFragOut {
    fixed3 Albedo;
    fixed Alpha;
    SPEEDTREE_DATA_NORMAL
};

// The surface of a SpeedTree pixel: diffuse texture times Input.color, the detail texture over
// it by the detail weight and the detail's alpha, the hue shift, the cut-out test
// (SPEEDTREE_ALPHATEST: alpha < _Cutoff is discarded) and the normal map.
void SpeedTreeFrag(Input IN, out SpeedTreeFragOut OUT) {
    half4 diffuse = tex2D(_MainTex, IN.mainTexUV);
    OUT.Alpha = diffuse.a * IN.color.a;
#ifdef SPEEDTREE_ALPHATEST
    clip(OUT.Alpha - _Cutoff);
#endif
#ifdef GEOM_TYPE_BRANCH_DETAIL
    half4 detail = tex2D(_DetailTex, IN.Detail.xy);
    diffuse.rgb = lerp(diffuse.rgb, detail.rgb, saturate(IN.Detail.z) * detail.a);
#endif
#ifdef EFFECT_HUE_VARIATION
    diffuse.rgb = VarcSpeedTreeShiftHue(diffuse.rgb, IN.HueVariationAmount);
#endif
    OUT.Albedo = diffuse.rgb * IN.color.rgb;
#if defined(EFFECT_BUMP) && !defined(LIGHTMAP_ON)
    OUT.Normal = UnpackNormal(tex2D(_BumpMap, IN.mainTexUV));
#endif
}

#endif // SPEEDTREE_COMMON_INCLUDED
