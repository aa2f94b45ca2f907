// SPDX-License-Identifier: Apache-2.0
// varc built-in: TerrainEngine.cginc. Vertex animation of terrain trees and grass: wind bending
// of tree-creator trees (main bending plus branch and leaf-edge detail, after the procedural
// vegetation animation of GPU Gems 3, chapter 16), squashing, camera-facing billboards and
// waving grass. The engine's per-frame values (_Wind, _WaveAndDistance, _CameraPosition, the
// billboard camera vectors) are ordinary uniforms here. Written for varc; not derived from Unity.
#ifndef TERRAIN_ENGINE_INCLUDED
#define TERRAIN_ENGINE_INCLUDED

#include "UnityCG.cginc"

// Tree-creator trees: the wind (xyz direction in object space, w strength), the terrain's bend
// matrix, the squash plane (xyz normal, w offset) and amount (1 = not squashed).
float4 _Wind;
float4x4 _TerrainEngineBendTree;
float4 _SquashPlaneNormal;
float _SquashAmount;
float4 _TreeInstanceScale;
fixed4 _TreeInstanceColor;

// Billboards and grass: the camera's position (w = 1 / fade range of grass), its right and up
// vectors in terrain space, the tree-billboard camera (front.w: billboard tilt, up.w: offset
// along the view), the billboard distances, and the grass waves: x time offset, y wave size,
// z wind amount, w squared cut-off distance.
float4 _CameraPosition;
float3 _CameraRight;
float3 _CameraUp;
float3 _TreeBillboardCameraRight;
float4 _TreeBillboardCameraUp;
float4 _TreeBillboardCameraFront;
float4 _TreeBillboardCameraPos;
float4 _TreeBillboardDistances;
float4 _WaveAndDistance;
fixed4 _WavingTint;

struct appdata_tree {
    float4 vertex : POSITION;
    float4 tangent : TANGENT;
    float3 normal : NORMAL;
    fixed4 color : COLOR;        // xy: branch phase and edge flutter, a: bend weight
    float4 texcoord : TEXCOORD0;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};
struct appdata_tree_billboard {
    float4 vertex : POSITION;
    fixed4 color : COLOR;
    float4 texcoord : TEXCOORD0;  // xy: uv, z: billboard width offset, w: height offset
    float2 texcoord1 : TEXCOORD1; // corner offset
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

// Periodic helpers of the wind animation, per component.
// SmoothCurve: the smoothstep polynomial 3x^2 - 2x^3 of x in [0, 1].
inline float4 SmoothCurve(float4 x) { return x * x * (3.0 - 2.0 * x); }
// TriangleWave: 1 at integers, 0 at half integers, linear in between (period 1). SpeedTreeWind.cginc
// defines the same function: whichever file comes first defines it.
#ifndef VARC_TRIANGLE_WAVE_DEFINED
#define VARC_TRIANGLE_WAVE_DEFINED
inline float4 TriangleWave(float4 x) { return abs(frac(x + 0.5) * 2.0 - 1.0); }
#endif
inline float4 SmoothTriangleWave(float4 x) { return SmoothCurve(TriangleWave(x)); }

// Sine and cosine of each component of val.
void FastSinCos(float4 val, out float4 s, out float4 c) {
    s = sin(val);
    c = cos(val);
}

// Wind animation of a tree-creator vertex. animParams: x branch phase, y leaf-edge flutter,
// z primary (trunk) bend factor, w secondary (branch) bend factor.
// Detail: four smoothed triangle waves of time, phased per branch and per vertex, move the
// vertex along its normal's xy (leaf edges) and along the wind (branches). Main bending: the
// vertex moves along the wind by a factor growing with its height (b^2 - b, b = (1 + y z)^2)
// and keeps its distance to the origin.
float4 AnimateVertex(float4 pos, float3 normal, float4 animParams) {
    float time = _Time.y * 0.5;
    float objectPhase = dot(unity_ObjectToWorld._14_24_34, 1);
    float branchPhase = objectPhase + animParams.x;
    float vertexPhase = dot(pos.xyz, animParams.y + branchPhase);
    float2 phases = time + float2(vertexPhase, branchPhase);
    float4 waves = frac(phases.xxyy * float4(1.975, 0.793, 0.375, 0.193)) * 2.0 - 1.0;
    waves = SmoothTriangleWave(waves);
    float2 sum = waves.xz + waves.yw;
    float3 bend = animParams.y * normal.xyz * 0.1;
    bend.y = animParams.w * 0.1;
    pos.xyz += (sum.xxy * bend) * _Wind.w;
    pos.xyz += animParams.w * _Wind.xyz * _Wind.w;

    float length0 = length(pos.xyz);
    float b = 1.0 + pos.y * animParams.z * 0.0025;
    b *= b;
    b = b * b - b;
    float3 moved = pos.xyz;
    moved.xz += _Wind.xz * b * _Wind.w;
    pos.xyz = normalize(moved) * length0;
    return pos;
}

// Moves the vertex towards the squash plane; _SquashAmount = 1 leaves it, 0 puts it on the plane.
inline float4 Squash(in float4 pos) {
    float distanceToPlane = dot(pos.xyz, _SquashPlaneNormal.xyz) + _SquashPlaneNormal.w;
    float3 onPlane = pos.xyz - distanceToPlane * _SquashPlaneNormal.xyz;
    pos.xyz = lerp(onPlane, pos.xyz, _SquashAmount);
    return pos;
}

// Terrain (soft-occlusion) trees: bends the vertex with the terrain's bend matrix in proportion
// to alpha (the vertex colour's alpha), then squashes it.
void TerrainAnimateTree(inout float4 pos, float alpha) {
    float3 bent = mul(_TerrainEngineBendTree, float4(pos.xyz, 0.0)).xyz;
    pos.xyz = lerp(pos.xyz, bent, alpha);
    pos = Squash(pos);
}

// Billboard vertices of legacy tree leaves (tangent.w == 0): normal.xy holds the corner offset in
// camera space and |mat| takes camera-space directions to object space (UNITY_MATRIX_IT_MV as a
// row-vector transform); the vertex moves to its corner and its normal and tangent turn to the
// camera. Other vertices are unchanged.
void ExpandBillboard(in float4x4 mat, inout float4 pos, inout float3 normal, inout float4 tangent) {
    float billboard = 1.0 - abs(tangent.w);
    float3 facingNormal = normalize(mul(float4(normal, 0.0), mat).xyz);
    float3 facingTangent = normalize(mul(float4(tangent.xyz, 0.0), mat).xyz);
    pos += mul(float4(normal.xy, 0.0, 0.0), mat) * billboard;
    normal = lerp(normal, facingNormal, billboard);
    tangent = lerp(tangent, float4(facingTangent, tangent.w), billboard);
}

// Grass billboards: the corner offset spans the camera's right and up vectors; grass beyond the
// cut-off distance collapses to a point.
void TerrainBillboardGrass(inout float4 pos, float2 offset) {
    float3 toGrass = pos.xyz - _CameraPosition.xyz;
    if (dot(toGrass, toGrass) > _WaveAndDistance.w)
        offset = 0.0;
    pos.xyz += offset.x * _CameraRight.xyz + offset.y * _CameraUp.xyz;
}

// Tree billboards: the corner offset spans the billboard camera's right and up vectors, and the
// quad is pushed along the view by offsetz * the camera's up.w.
void TerrainBillboardTree(inout float4 pos, float2 offset, float offsetz) {
    pos.xyz += _TreeBillboardCameraRight.xyz * offset.x;
    pos.xyz += _TreeBillboardCameraUp.xyz * lerp(offset.y, offsetz, _TreeBillboardCameraFront.w);
    pos.xyz += _TreeBillboardCameraFront.xyz * (offsetz * _TreeBillboardCameraUp.w);
    pos.w = 1.0;
}

// Waving grass: four travelling sine waves over the grass position move the vertex in x and z
// (scaled by waveAmount and the wind), brighten or darken its colour towards _WavingTint as it
// waves, and fade its alpha out towards the cut-off distance. Returns the new colour.
fixed4 TerrainWaveGrass(inout float4 vertex, float waveAmount, fixed4 color) {
    const float4 speed = float4(1.2, 2.0, 1.6, 4.8);
    const float4 xFrequency = float4(0.012, 0.02, 0.06, 0.024);
    const float4 zFrequency = float4(0.006, 0.02, -0.02, 0.1);
    float4 phase = (vertex.x * xFrequency + vertex.z * zFrequency) * _WaveAndDistance.y
                 + _WaveAndDistance.x * speed;
    float4 s, c;
    FastSinCos(frac(phase) * 6.2831853 - 3.1415927, s, c);
    s *= s;
    s *= s;
    float lighting = dot(s, normalize(float4(1, 1, 0.4, 0.2))) * 0.7;
    s *= waveAmount;
    vertex.x -= dot(s, float4(0.024, 0.04, -0.12, 0.096)) * _WaveAndDistance.z;
    vertex.z -= dot(s, float4(0.006, 0.02, -0.02, 0.1)) * _WaveAndDistance.z;
    fixed3 tint = lerp(0.5, _WavingTint.rgb, lighting);
    color.rgb = color.rgb * tint * 2.0;
    float3 toCamera = vertex.xyz - _CameraPosition.xyz;
    color.a = saturate(2.0 * (_WaveAndDistance.w - dot(toCamera, toCamera)) * _CameraPosition.w);
    return color;
}

// Vertex functions of the terrain's grass shaders.
void WavingGrassVert(inout appdata_full v) {
    float waveAmount = v.color.a * _WaveAndDistance.z;
    v.color = TerrainWaveGrass(v.vertex, waveAmount, v.color);
}
void WavingGrassBillboardVert(inout appdata_full v) {
    TerrainBillboardGrass(v.vertex, v.tangent.xy);
    float waveAmount = v.tangent.y;
    v.color = TerrainWaveGrass(v.vertex, waveAmount, v.color);
}

#endif // TERRAIN_ENGINE_INCLUDED
