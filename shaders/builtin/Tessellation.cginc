// SPDX-License-Identifier: Apache-2.0
// varc built-in: Tessellation.cginc. Tessellation-factor helpers of surface shaders with
// `tessellate:` (and hand-written hull shaders): factors falling off with the distance to the
// camera, factors that keep triangle edges near a length in pixels, and frustum culling of
// patches. The returned float4 is (edge 0, edge 1, edge 2, inside); edge i is the edge opposite
// vertex i. Written for varc from the documented behaviour (Unity manual, "Surface Shaders with
// DX11 / OpenGL Core Tessellation"); not derived from Unity.
#ifndef TESSELLATION_CGINC_INCLUDED
#define TESSELLATION_CGINC_INCLUDED

#include "UnityShaderVariables.cginc"

// Signed distance of pos from the plane (n, d): dot(n, pos) + d.
float UnityDistanceFromPlane(float3 pos, float4 plane) {
    return dot(float4(pos, 1.0), plane);
}

// True when the triangle is entirely outside one of the camera's left, right, bottom and top
// planes (unity_CameraWorldClipPlanes, normals inside), each moved out by cullEps.
bool UnityWorldViewFrustumCull(float3 wpos0, float3 wpos1, float3 wpos2, float cullEps) {
    float4 planeTest;
    [unroll] for (int i = 0; i < 4; i++) {
        float4 plane = unity_CameraWorldClipPlanes[i];
        planeTest[i] = ((UnityDistanceFromPlane(wpos0, plane) > -cullEps) ? 1.0 : 0.0) +
                       ((UnityDistanceFromPlane(wpos1, plane) > -cullEps) ? 1.0 : 0.0) +
                       ((UnityDistanceFromPlane(wpos2, plane) > -cullEps) ? 1.0 : 0.0);
    }
    return !all(planeTest);
}

// Per-vertex factor: tess at minDist from the camera or closer, falling linearly to 1% of it at
// maxDist and beyond (vertex in object space).
float UnityCalcDistanceTessFactor(float4 vertex, float minDist, float maxDist, float tess) {
    float3 wpos = mul(unity_ObjectToWorld, vertex).xyz;
    float dist = distance(wpos, _WorldSpaceCameraPos);
    return clamp(1.0 - (dist - minDist) / (maxDist - minDist), 0.01, 1.0) * tess;
}

// Triangle factors from per-vertex factors: each edge the mean of its two vertices, the inside
// the mean of the three.
float4 UnityCalcTriEdgeTessFactors(float3 triVertexFactors) {
    float4 tess;
    tess.x = 0.5 * (triVertexFactors.y + triVertexFactors.z);
    tess.y = 0.5 * (triVertexFactors.x + triVertexFactors.z);
    tess.z = 0.5 * (triVertexFactors.x + triVertexFactors.y);
    tess.w = (triVertexFactors.x + triVertexFactors.y + triVertexFactors.z) / 3.0;
    return tess;
}

// Factor that splits the world-space edge (wpos0, wpos1) into pieces of about edgeLen pixels:
// its length times the screen height, over edgeLen times its middle's distance to the camera.
float UnityCalcEdgeTessFactor(float3 wpos0, float3 wpos1, float edgeLen) {
    float dist = distance(0.5 * (wpos0 + wpos1), _WorldSpaceCameraPos);
    float len = distance(wpos0, wpos1);
    return max(len * _ScreenParams.y / (edgeLen * dist), 1.0);
}

float4 UnityDistanceBasedTess(float4 v0, float4 v1, float4 v2, float minDist, float maxDist, float tess) {
    float3 f;
    f.x = UnityCalcDistanceTessFactor(v0, minDist, maxDist, tess);
    f.y = UnityCalcDistanceTessFactor(v1, minDist, maxDist, tess);
    f.z = UnityCalcDistanceTessFactor(v2, minDist, maxDist, tess);
    return UnityCalcTriEdgeTessFactors(f);
}

float4 UnityEdgeLengthBasedTess(float4 v0, float4 v1, float4 v2, float edgeLength) {
    float3 pos0 = mul(unity_ObjectToWorld, v0).xyz;
    float3 pos1 = mul(unity_ObjectToWorld, v1).xyz;
    float3 pos2 = mul(unity_ObjectToWorld, v2).xyz;
    float4 tess;
    tess.x = UnityCalcEdgeTessFactor(pos1, pos2, edgeLength);
    tess.y = UnityCalcEdgeTessFactor(pos2, pos0, edgeLength);
    tess.z = UnityCalcEdgeTessFactor(pos0, pos1, edgeLength);
    tess.w = (tess.x + tess.y + tess.z) / 3.0;
    return tess;
}

// As UnityEdgeLengthBasedTess, but 0 (the patch is dropped) when the triangle, grown by
// maxDisplacement, is outside the view frustum.
float4 UnityEdgeLengthBasedTessCull(float4 v0, float4 v1, float4 v2, float edgeLength, float maxDisplacement) {
    float3 pos0 = mul(unity_ObjectToWorld, v0).xyz;
    float3 pos1 = mul(unity_ObjectToWorld, v1).xyz;
    float3 pos2 = mul(unity_ObjectToWorld, v2).xyz;
    if (UnityWorldViewFrustumCull(pos0, pos1, pos2, maxDisplacement))
        return 0.0;
    return UnityEdgeLengthBasedTess(v0, v1, v2, edgeLength);
}

#endif // TESSELLATION_CGINC_INCLUDED
