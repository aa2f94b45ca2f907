// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityBuiltin3xTreeLibrary.cginc. Tree-creator (Nature/Tree Creator) bark and leaf
// vertex functions (instance scale and colour, wind animation, squashing, leaf billboards), the
// translucent leaf lighting model TreeLeaf and its per-vertex form, and the LOD-fade dither
// helpers. Written for varc from the documented behaviour; not derived from Unity.
#ifndef UNITY_BUILTIN_3X_TREE_LIBRARY_INCLUDED
#define UNITY_BUILTIN_3X_TREE_LIBRARY_INCLUDED

#include "UnityCG.cginc"
#include "Lighting.cginc"
#include "TerrainEngine.cginc"

fixed4 _Color;
fixed3 _TranslucencyColor;
fixed _TranslucencyViewDependency;
half _ShadowStrength;

// Surface output of the tree-creator leaf shaders: Blinn-Phong terms plus Translucency, the
// share of light passing through the leaf.
struct LeafSurfaceOutput {
    fixed3 Albedo;
    fixed3 Normal;
    fixed3 Emission;
    fixed Translucency;
    half Specular;
    fixed Gloss;
    fixed Alpha;
};

// Tree vertices: scaled by the tree instance, animated by the wind (vertex colour xy: branch
// phase and leaf-edge flutter; texcoord1 xy: primary and secondary bend factors), squashed,
// tinted by the instance and material colours; normal and tangent renormalised.
void TreeVertBark(inout appdata_full v) {
    v.vertex.xyz *= _TreeInstanceScale.xyz;
    v.vertex = AnimateVertex(v.vertex, v.normal, float4(v.color.xy, v.texcoord1.xy));
    v.vertex = Squash(v.vertex);
    v.color.rgb = _TreeInstanceColor.rgb * _Color.rgb;
    v.normal = normalize(v.normal);
    v.tangent.xyz = normalize(v.tangent.xyz);
}

// Leaves also expand their camera-facing billboard corners first (ExpandBillboard).
void TreeVertLeaf(inout appdata_full v) {
    ExpandBillboard(UNITY_MATRIX_IT_MV, v.vertex, v.normal, v.tangent);
    v.vertex.xyz *= _TreeInstanceScale.xyz;
    v.vertex = AnimateVertex(v.vertex, v.normal, float4(v.color.xy, v.texcoord1.xy));
    v.vertex = Squash(v.vertex);
    v.color.rgb = _TreeInstanceColor.rgb * _Color.rgb;
    v.normal = normalize(v.normal);
    v.tangent.xyz = normalize(v.tangent.xyz);
}

// Lighting of the back side of a leaf seen against the light: between the wrapped back-face
// term saturate(-N.L) and the view-dependent term saturate(V.-L), by
// _TranslucencyViewDependency, times the surface's translucency and _TranslucencyColor.
inline half3 VarcLeafTranslucency(half3 normal, half3 lightDir, half3 viewDir, half translucency) {
    half back = saturate(dot(viewDir, -lightDir));
    half wrapped = saturate(-dot(normal, lightDir));
    return lerp(wrapped, back, _TranslucencyViewDependency) * translucency * _TranslucencyColor;
}

// TreeLeaf lighting model (surface shaders: `#pragma surface surf TreeLeaf`): half-wrapped
// diffuse max(0, N.L * 0.6 + 0.4), twice the translucency, Blinn-Phong specular
// pow(N.H, Specular * 128) * Gloss; the shadow attenuation is weakened by _ShadowStrength.
half4 LightingTreeLeaf(LeafSurfaceOutput s, half3 lightDir, half3 viewDir, half atten) {
    half3 h = normalize(lightDir + viewDir);
    half nl = dot(s.Normal, lightDir);
    half nh = max(0, dot(s.Normal, h));
    half specular = pow(nh, s.Specular * 128.0) * s.Gloss;
    half3 translucency = VarcLeafTranslucency(s.Normal, lightDir, viewDir, s.Translucency);
    half diffuse = max(0, nl * 0.6 + 0.4);
    atten = lerp(1, atten, _ShadowStrength);
    half4 c;
    c.rgb = s.Albedo * (translucency * 2 + diffuse) * _LightColor0.rgb * atten
          + _LightColor0.rgb * specular * atten;
    c.a = s.Alpha;
    return c;
}

// Per-vertex form of TreeLeaf's diffuse and translucent terms for the main light (object
// space), without specular or shadows.
fixed3 ShadeTranslucentMainLight(float4 vertex, float3 normal) {
    float3 viewDir = normalize(ObjSpaceViewDir(vertex));
    float3 lightDir = normalize(ObjSpaceLightDir(vertex));
    half nl = dot(normal, lightDir);
    half3 translucency = VarcLeafTranslucency(normal, lightDir, viewDir, 1.0);
    return _LightColor0.rgb * (max(0, nl * 0.6 + 0.4) + translucency * 2);
}

// The same summed over the main light and the four per-vertex point lights (unity_4LightPos*,
// unity_LightColor[0..3], attenuation 1 / (1 + d^2 unity_4LightAtten0)).
fixed3 ShadeTranslucentLights(float4 vertex, float3 normal) {
    float3 viewDir = normalize(ObjSpaceViewDir(vertex));
    float3 worldPos = mul(unity_ObjectToWorld, vertex).xyz;
    float3 worldNormal = UnityObjectToWorldNormal(normal);
    float3 worldView = normalize(UnityWorldSpaceViewDir(worldPos));
    fixed3 light = ShadeTranslucentMainLight(vertex, normal);
    float4 lightPosX = unity_4LightPosX0, lightPosY = unity_4LightPosY0, lightPosZ = unity_4LightPosZ0;
    for (int i = 0; i < 4; i++) {
        float3 toLight = float3(lightPosX[i], lightPosY[i], lightPosZ[i]) - worldPos;
        float lengthSq = max(dot(toLight, toLight), 0.000001);
        float3 lightDir = toLight * rsqrt(lengthSq);
        float atten = 1.0 / (1.0 + lengthSq * unity_4LightAtten0[i]);
        half nl = dot(worldNormal, lightDir);
        half3 translucency = VarcLeafTranslucency(worldNormal, lightDir, worldView, 1.0);
        light += unity_LightColor[i].rgb * (max(0, nl * 0.6 + 0.4) + translucency * 2) * atten;
    }
    return light;
}

// LOD-fade dithering: 1 where the pixel (x, y) of a 4 x 4 ordered-dither tile keeps coverage
// c0 in [0, 1] (its threshold, (rank + 0.5) / 16, is below c0), else 0.
float ScreenDitherToAlpha(float x, float y, float c0) {
    static const float thresholds[16] = {
        0.03125, 0.53125, 0.15625, 0.65625, 0.78125, 0.28125, 0.90625, 0.40625,
        0.21875, 0.71875, 0.09375, 0.59375, 0.96875, 0.46875, 0.84375, 0.34375};
    uint2 cell = uint2(x, y) & 3u;
    return c0 > thresholds[cell.y * 4u + cell.x] ? 1.0 : 0.0;
}

// Alpha for alpha-to-coverage of a tree fading by fadeAmount, dithered at the pixel of
// screenPos (ComputeScreenPos). 1 when LOD_FADE_CROSSFADE is off.
float ComputeAlphaCoverage(float4 screenPos, float fadeAmount) {
#if defined(LOD_FADE_CROSSFADE)
    float2 pixel = screenPos.xy / screenPos.w * _ScreenParams.xy;
    return ScreenDitherToAlpha(pixel.x, pixel.y, fadeAmount);
#else
    return 1.0;
#endif
}

#endif // UNITY_BUILTIN_3X_TREE_LIBRARY_INCLUDED
