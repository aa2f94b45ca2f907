// SPDX-License-Identifier: Apache-2.0
// varc built-in: SpeedTreeBillboardCommon.cginc. SpeedTree (7) billboards, the far LOD of a
// tree: SpeedTreeBillboardVert turns each quad about the vertical to face the camera and picks
// the atlas image photographed from the nearest angle; the fragment side is SpeedTreeCommon's.
// Written for varc from the documented behaviour; not derived from Unity or SpeedTree.
//
// Geometry (object space, Y up):
//   vertex.xyz       the tree's base; texcoord.xy the quad corner in [0, 1]^2 (x across, y up);
//   texcoord1        x the tree's rotation about Y (radians), y its width scale, z its height
//                    scale (0 is taken as 1), w unused
//   unity_BillboardSize  (width, height, bottom, unused): a quad spans x in [-width/2, width/2]
//                    and y in [-bottom, height - bottom] about the base, times the scales
//   unity_BillboardInfo  x the number of images around the tree (1..16), image i photographed
//                    from the angle 2 pi i / count measured from +Z towards +X
//   unity_BillboardImageTexCoords[i]  (u, v, width, height) of image i in the atlas
//   unity_BillboardCameraParams  xyz the camera position, w the yaw of the direction from the
//                    trees to the camera (from +Z towards +X); with BILLBOARD_FACE_CAMERA_POS
//                    each quad faces the camera position, otherwise all face along the yaw
//   unity_BillboardNormal, unity_BillboardTangent  the renderer's billboard frame; the quads
//                    here take theirs from the facing direction (normal towards the camera,
//                    tangent across, bitangent up)
#ifndef SPEEDTREE_BILLBOARD_COMMON_INCLUDED
#define SPEEDTREE_BILLBOARD_COMMON_INCLUDED

#include "HLSLSupport.cginc"

// Billboards are cut out at alpha _Cutoff (declared before SpeedTreeFrag reads it).
#define SPEEDTREE_ALPHATEST
#if !(defined(GEOM_TYPE_FROND) || defined(GEOM_TYPE_LEAF) || defined(GEOM_TYPE_FACING_LEAF))
fixed _Cutoff;  // SpeedTreeCommon.cginc declares it for fronds and leaves
#endif

#include "SpeedTreeCommon.cginc"

CBUFFER_START(UnityBillboardPerCamera)
    float3 unity_BillboardNormal;
    float3 unity_BillboardTangent;
    float4 unity_BillboardCameraParams;
CBUFFER_END

CBUFFER_START(UnityBillboardPerBatch)
    float4 unity_BillboardInfo;
    float4 unity_BillboardSize;
    float4 unity_BillboardImageTexCoords[16];
CBUFFER_END

#define unity_BillboardCameraPosition (unity_BillboardCameraParams.xyz)
#define unity_BillboardCameraXZAngle (unity_BillboardCameraParams.w)

struct SpeedTreeBillboardData {
    float4 vertex : POSITION;
    float2 texcoord : TEXCOORD0;
    float4 texcoord1 : TEXCOORD1;
    float3 normal : NORMAL;
    float4 tangent : TANGENT;
    float4 color : COLOR;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

// The unit horizontal direction from the billboard at |base| to the camera.
float3 VarcBillboardToCamera(float3 base) {
#ifdef BILLBOARD_FACE_CAMERA_POS
    float3 toCamera = unity_BillboardCameraPosition - base;
    toCamera.y = 0.0;
    float lengthSquared = dot(toCamera, toCamera);
    return lengthSquared > 1e-12 ? toCamera * rsqrt(lengthSquared) : float3(0.0, 0.0, 1.0);
#else
    float yaw = unity_BillboardCameraXZAngle;
    return float3(sin(yaw), 0.0, cos(yaw));
#endif
}

// The image of the tree seen from |toCamera| (unit, horizontal) when the tree is turned by
// |rotation| radians: the nearest of unity_BillboardInfo.x angles.
int VarcBillboardImage(float3 toCamera, float rotation) {
    float count = max(unity_BillboardInfo.x, 1.0);
    float turns = atan2(toCamera.x, toCamera.z) / UNITY_TWO_PI - rotation / UNITY_TWO_PI;
    return (int)min(floor(frac(turns + 0.5 / count) * count), count - 1.0);
}

// The vertex function of `#pragma surface ... vertex:SpeedTreeBillboardVert`: places the
// corner, sets the normal (towards the camera) and tangent (across, w 1: bitangent up), picks
// the image's UV, sways with the global wind (ENABLE_WIND) and fills |OUT| as SpeedTreeVert.
void SpeedTreeBillboardVert(inout SpeedTreeBillboardData IN, out Input OUT) {
    UNITY_SETUP_INSTANCE_ID(IN);
    UNITY_INITIALIZE_OUTPUT(Input, OUT);
    float3 base = IN.vertex.xyz;
    float3 toCamera = VarcBillboardToCamera(base);
    float3 across = float3(toCamera.z, 0.0, -toCamera.x);
    float width = unity_BillboardSize.x * (IN.texcoord1.y != 0.0 ? IN.texcoord1.y : 1.0);
    float height = IN.texcoord1.z != 0.0 ? IN.texcoord1.z : 1.0;
    float3 corner = across * ((IN.texcoord.x - 0.5) * width) +
                    float3(0.0, (IN.texcoord.y * unity_BillboardSize.y - unity_BillboardSize.z) * height, 0.0);
#ifdef ENABLE_WIND
    if (_WindEnabled > 0.0 && _WindQuality > WIND_QUALITY_NONE) {
        float3 wind = mul((float3x3)unity_WorldToObject, _ST_WindVector.xyz);
        corner = GlobalWind(corner, base, true, wind, _ST_WindGlobal.x);
    }
#endif
    IN.vertex.xyz = base + corner;
    IN.normal = toCamera;
    IN.tangent = float4(across, 1.0);
    float4 image = unity_BillboardImageTexCoords[VarcBillboardImage(toCamera, IN.texcoord1.x)];
    OUT.mainTexUV = image.xy + IN.texcoord.xy * image.zw;
    OUT.color = _Color;
    OUT.interpolator1.z = VarcSpeedTreeHueVariation(mul(unity_ObjectToWorld, float4(base, 1.0)).xyz, 0.0);
    IN.color = OUT.color;
    UNITY_TRANSFER_DITHER_CROSSFADE(OUT, IN.vertex)
}

#endif // SPEEDTREE_BILLBOARD_COMMON_INCLUDED
