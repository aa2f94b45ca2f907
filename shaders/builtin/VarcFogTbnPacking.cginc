// SPDX-License-Identifier: Apache-2.0
// varc built-in: the interpolator packing of Unity 2018.4+'s generated surface-shader code
// (included by UnityCG.cginc): the fog coordinate shares a vector with the tangent frame
// (tSpace0..2), the world position (worldPos.w) or the eye vector (eyeVec.w), and the fragment
// stage unpacks it (_unity_fogCoord) and the frame (_unity_tbn_0..2). Written for varc.
#ifndef VARC_FOG_TBN_PACKING_INCLUDED
#define VARC_FOG_TBN_PACKING_INCLUDED

// The tangent frame travels as three rows tSpaceN = (tangent.N, binormal.N, normal.N, worldPos.N):
// _unity_tbn_N is row N, _unity_tangent / _unity_binormal / _unity_normal the columns.
#define UNITY_EXTRACT_TBN_0(name) fixed3 _unity_tbn_0 = (name).tSpace0.xyz
#define UNITY_EXTRACT_TBN_1(name) fixed3 _unity_tbn_1 = (name).tSpace1.xyz
#define UNITY_EXTRACT_TBN_2(name) fixed3 _unity_tbn_2 = (name).tSpace2.xyz
#define UNITY_EXTRACT_TBN(name) UNITY_EXTRACT_TBN_0(name); UNITY_EXTRACT_TBN_1(name); UNITY_EXTRACT_TBN_2(name)
#define UNITY_EXTRACT_TBN_T(name) fixed3 _unity_tangent = fixed3((name).tSpace0.x, (name).tSpace1.x, (name).tSpace2.x)
#define UNITY_EXTRACT_TBN_N(name) fixed3 _unity_normal = fixed3((name).tSpace0.z, (name).tSpace1.z, (name).tSpace2.z)
#define UNITY_EXTRACT_TBN_B(name) fixed3 _unity_binormal = cross(_unity_normal, _unity_tangent)
// When the fog coordinate took the binormal's z (tSpace2.y, below), the binormal is rebuilt as
// +-cross(normal, tangent), the sign that of its x and y that are still there.
#define UNITY_CORRECT_TBN_B_SIGN(name) _unity_binormal *= (dot(_unity_binormal.xy, fixed2((name).tSpace0.y, (name).tSpace1.y)) < 0.0 ? -1.0 : 1.0)
#define UNITY_RECONSTRUCT_TBN_0 fixed3 _unity_tbn_0 = fixed3(_unity_tangent.x, _unity_binormal.x, _unity_normal.x)
#define UNITY_RECONSTRUCT_TBN_1 fixed3 _unity_tbn_1 = fixed3(_unity_tangent.y, _unity_binormal.y, _unity_normal.y)
#define UNITY_RECONSTRUCT_TBN_2 fixed3 _unity_tbn_2 = fixed3(_unity_tangent.z, _unity_binormal.z, _unity_normal.z)

// The fog coordinate is the eye depth (clip w), as UNITY_TRANSFER_FOG stores it; the fragment
// stage reads it into _unity_fogCoord for UNITY_APPLY_FOG. Without fog nothing is packed, and
// the frame is read as it is.
#if defined(FOG_LINEAR) || defined(FOG_EXP) || defined(FOG_EXP2)
    #define UNITY_TRANSFER_FOG_COMBINED_WITH_TSPACE(o, outpos) (o).tSpace2.y = (outpos).w
    #define UNITY_TRANSFER_FOG_COMBINED_WITH_WORLD_POS(o, outpos) (o).worldPos.w = (outpos).w
    #define UNITY_TRANSFER_FOG_COMBINED_WITH_EYE_VEC(o, outpos) (o).eyeVec.w = (outpos).w
    #define UNITY_EXTRACT_FOG_FROM_TSPACE(name) float _unity_fogCoord = (name).tSpace2.y
    #define UNITY_EXTRACT_FOG_FROM_WORLD_POS(name) float _unity_fogCoord = (name).worldPos.w
    #define UNITY_EXTRACT_FOG_FROM_EYE_VEC(name) float _unity_fogCoord = (name).eyeVec.w
    #define UNITY_RECONSTRUCT_TBN(name) UNITY_EXTRACT_TBN_T(name); UNITY_EXTRACT_TBN_N(name); UNITY_EXTRACT_TBN_B(name); UNITY_CORRECT_TBN_B_SIGN(name); UNITY_RECONSTRUCT_TBN_0; UNITY_RECONSTRUCT_TBN_1; UNITY_RECONSTRUCT_TBN_2
#else
    #define UNITY_TRANSFER_FOG_COMBINED_WITH_TSPACE(o, outpos)
    #define UNITY_TRANSFER_FOG_COMBINED_WITH_WORLD_POS(o, outpos)
    #define UNITY_TRANSFER_FOG_COMBINED_WITH_EYE_VEC(o, outpos)
    #define UNITY_EXTRACT_FOG_FROM_TSPACE(name)
    #define UNITY_EXTRACT_FOG_FROM_WORLD_POS(name)
    #define UNITY_EXTRACT_FOG_FROM_EYE_VEC(name)
    #define UNITY_RECONSTRUCT_TBN(name) UNITY_EXTRACT_TBN(name)
#endif

#endif // VARC_FOG_TBN_PACKING_INCLUDED
