// SPDX-License-Identifier: Apache-2.0
// varc built-in: SpeedTreeVertex.cginc. The SpeedTree (7) vertex: its input layout SpeedTreeVB
// and OffsetSpeedTreeVertex, which blends towards the next LOD, turns facing leaves to the camera
// and applies the wind (SpeedTreeWind.cginc, with ENABLE_WIND). Written for varc from the
// documented behaviour; not derived from Unity or SpeedTree.
//
// Vertex layout varc's SpeedTree functions read (object space, Y up, the tree's base at 0):
//   texcoord.xy   diffuse UV; texcoord.zw branch wind (weight: 0 at the trunk, 1 at the tips;
//                 phase offset)
//   texcoord1.xyz the vertex's position in the next, coarser LOD; texcoord1.w the leaf or frond
//                 wind scale
//   texcoord2.xyz leaves: the card's anchor (its centre); texcoord2.w the packed growth
//                 direction. Branches with detail (GEOM_TYPE_BRANCH_DETAIL): detail UV in xy,
//                 detail weight in z
//   texcoord3.x   the packed ripple direction (UnpackNormalFromFloat; 0: a one-sided frond);
//                 texcoord3.y 1 for leaves of the second leaf group
//   color.r       ambient occlusion
#ifndef SPEEDTREE_VERTEX_INCLUDED
#define SPEEDTREE_VERTEX_INCLUDED

#include "UnityCG.cginc"

#ifdef ENABLE_WIND
// _WindQuality's values: what the tree's wind settings ask for; each level adds motion.
#define WIND_QUALITY_NONE 0
#define WIND_QUALITY_FASTEST 1
#define WIND_QUALITY_FAST 2
#define WIND_QUALITY_BETTER 3
#define WIND_QUALITY_BEST 4
#define WIND_QUALITY_PALM 5

half _WindQuality;  // a WIND_QUALITY_* value
half _WindEnabled;  // 0 turns the wind off for this renderer
#include "SpeedTreeWind.cginc"
#endif

struct SpeedTreeVB {
    float4 vertex : POSITION;
    float4 tangent : TANGENT;
    float3 normal : NORMAL;
    float4 texcoord : TEXCOORD0;
    float4 texcoord1 : TEXCOORD1;
    float4 texcoord2 : TEXCOORD2;
    float2 texcoord3 : TEXCOORD3;
    half4 color : COLOR;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

// The camera's right, up and backward axes in object space (the rows of the view matrix).
float3x3 VarcSpeedTreeCameraAxesInObject() {
    float3x3 toObject = (float3x3)unity_WorldToObject;
    return float3x3(normalize(mul(toObject, UNITY_MATRIX_V[0].xyz)),
                    normalize(mul(toObject, UNITY_MATRIX_V[1].xyz)),
                    normalize(mul(toObject, UNITY_MATRIX_V[2].xyz)));
}

// A facing leaf's corner: its offset from the anchor, read as (right, up, towards the camera),
// laid along the camera's axes, so that the card faces the camera whatever the tree's rotation.
float3 VarcSpeedTreeFaceCamera(float3 vPos, float3 anchor) {
    float3x3 axes = VarcSpeedTreeCameraAxesInObject();
    float3 offset = vPos - anchor;
    return anchor + axes[0] * offset.x + axes[1] * offset.y + axes[2] * offset.z;
}

#ifdef ENABLE_WIND
// The wind of one vertex at quality |quality| (WIND_QUALITY_*): the rotated wind and branch
// anchor are the uniforms taken to object space, so a rotated tree bends with the world's wind.
// The geometry keywords choose which parts apply: fronds ripple (better and up), leaves ripple
// (fast and up) and tumble (best), branch and frond vertices sway (better and up), and every
// vertex follows the global bend (fastest and up).
float3 VarcSpeedTreeWind(float3 vPos, inout float3 normal, float4 texcoord, float4 texcoord1,
                         float4 texcoord2, float2 texcoord3, float3 binormal, float3 tangent,
                         float quality) {
    float3 wind = mul((float3x3)unity_WorldToObject, _ST_WindVector.xyz);
    float3 anchor = mul((float3x3)unity_WorldToObject, _ST_WindBranchAnchor.xyz) * _ST_WindBranchAnchor.w;
    float3 instance = unity_ObjectToWorld._m03_m13_m23;
    bool palm = quality == WIND_QUALITY_PALM;
#if defined(GEOM_TYPE_FROND)
    if (quality >= WIND_QUALITY_BETTER) {
        vPos = RippleFrond(vPos, normal, texcoord.x, texcoord.y, texcoord3.x, texcoord1.w,
                           texcoord1.w, binormal, tangent);
    }
#elif defined(GEOM_TYPE_LEAF) || defined(GEOM_TYPE_FACING_LEAF)
    if (quality >= WIND_QUALITY_FAST) {
        vPos = LeafWind(quality >= WIND_QUALITY_BEST, texcoord3.y > 0.5, vPos, normal,
                        texcoord1.w, texcoord2.xyz, texcoord2.w, texcoord3.x,
                        dot(texcoord2.xyz, float3(1.0, 1.0, 1.0)), wind);
    }
#endif
    if (quality >= WIND_QUALITY_BETTER) {
        vPos = BranchWind(palm, vPos, instance, float4(texcoord.zw, 0.0, 0.0), wind, anchor);
    }
    if (quality >= WIND_QUALITY_FASTEST) vPos = GlobalWind(vPos, instance, true, wind, _ST_WindGlobal.x);
    return vPos;
}
#endif

// Moves |data| for LOD |lodValue|: with LOD_FADE_PERCENTAGE the position blends from this LOD's
// (lodValue 0) to the next LOD's (texcoord1.xyz, lodValue 1); facing leaves turn to the camera;
// with ENABLE_WIND the wind of quality _WindQuality applies unless _WindEnabled is 0.
void OffsetSpeedTreeVertex(inout SpeedTreeVB data, float lodValue) {
    float3 position = data.vertex.xyz;
#ifdef LOD_FADE_PERCENTAGE
    position = lerp(position, data.texcoord1.xyz, lodValue);
#endif
#ifdef GEOM_TYPE_FACING_LEAF
    position = VarcSpeedTreeFaceCamera(position, data.texcoord2.xyz);
#endif
#ifdef ENABLE_WIND
    if (_WindEnabled > 0.0) {
        float3 normal = data.normal;
        float3 binormal = cross(data.normal, data.tangent.xyz) * data.tangent.w;
        position = VarcSpeedTreeWind(position, normal, data.texcoord, data.texcoord1,
                                     data.texcoord2, data.texcoord3, binormal, data.tangent.xyz,
                                     _WindQuality);
        data.normal = normal;
    }
#endif
    data.vertex.xyz = position;
}

#endif // SPEEDTREE_VERTEX_INCLUDED
