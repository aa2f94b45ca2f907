// SPDX-License-Identifier: Apache-2.0
// Runs UnityCG.cginc's fog macros (coordinates, transfer, the packed forms of generated surface
// code, the factor and the colour blend) over a full-target quad for
// tests/vulkan/FogMacroValueTest.cpp. The vertex stage hands the macros a made-up clip position
// whose w (the eye depth the fog coordinate carries) runs 2..32 with u; pixel centre (u, v) is
// the input and each variant writes four floats.
Shader "Test/FogMacroValues" {
    SubShader {
        Pass {
            Cull Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile_fog
            #pragma multi_compile FG_APPLY FG_FACTOR FG_PACKED FG_COMBINED FG_TBN
            #include "UnityCG.cginc"

            struct Interpolators {
                float4 pos : SV_POSITION;
                float2 uv : TEXCOORD0;
            #if defined(FG_PACKED)
                UNITY_FOG_COORDS_PACKED(1, float4)
            #elif defined(FG_COMBINED) || defined(FG_TBN)
                float4 tSpace0 : TEXCOORD1;
                float4 tSpace1 : TEXCOORD2;
                float4 tSpace2 : TEXCOORD3;
                float4 worldPos : TEXCOORD4;
                float4 eyeVec : TEXCOORD5;
            #else
                UNITY_FOG_COORDS(1)
            #endif
            };

            Interpolators vert(float4 vertex : POSITION, float2 uv : TEXCOORD0) {
                Interpolators o = (Interpolators)0;
                o.pos = float4(vertex.xy, 0.5, 1.0);
                o.uv = uv;
                float4 fogClip = float4(0.0, 0.0, 0.0, 2.0 + 30.0 * uv.x);
            #if defined(FG_PACKED)
                // The other three components carry the caller's own data, written after the
                // transfer (as the Standard shader's simple path does).
                o.fogCoord = float4(7.0, 0.0, 0.0, 0.0);
                UNITY_TRANSFER_FOG(o, fogClip);
                o.fogCoord.yzw = float3(uv.y, 0.25, 0.5);
            #elif defined(FG_COMBINED)
                o.tSpace2 = float4(0.1, 0.2, 0.3, 0.4);
                o.worldPos = float4(1.0, 2.0, 3.0, 4.0);
                o.eyeVec = float4(0.5, 0.6, 0.7, 0.8);
                UNITY_TRANSFER_FOG_COMBINED_WITH_TSPACE(o, fogClip);
                UNITY_TRANSFER_FOG_COMBINED_WITH_WORLD_POS(o, fogClip * 0.5);
                UNITY_TRANSFER_FOG_COMBINED_WITH_EYE_VEC(o, fogClip * 0.25);
            #elif !defined(FG_TBN)
                UNITY_TRANSFER_FOG(o, fogClip);
            #endif
                return o;
            }

            float4 frag(Interpolators i) : SV_Target {
                float u = i.uv.x, v = i.uv.y;
                fixed4 col = fixed4(u, v, 0.5, 0.8);
            #if defined(FG_APPLY)
                UNITY_APPLY_FOG(i.fogCoord, col);
                return col;
            #elif defined(FG_FACTOR)
                // The factor itself (0 without fog) and an explicit blend towards a fixed colour.
                float factor = 0.0;
                {
                    UNITY_CALC_FOG_FACTOR_RAW(i.fogCoord.x * 0.5);
                    factor = unityFogFactor;
                }
                fixed4 other = col;
                UNITY_APPLY_FOG_COLOR(i.fogCoord, other, fixed4(0.1, 0.9, 0.3, 1.0));
            #if defined(FOG_LINEAR) || defined(FOG_EXP) || defined(FOG_EXP2)
                UNITY_EXTRACT_FOG(i);
                {
                    UNITY_CALC_FOG_FACTOR(_unity_fogCoord);
                    UNITY_FOG_LERP_COLOR(col, fixed4(1.0, 1.0, 1.0, 1.0), unityFogFactor);
                }
            #else
                // The blend itself exists without fog too.
                UNITY_FOG_LERP_COLOR(col, fixed4(1.0, 1.0, 1.0, 1.0), 0.25);
            #endif
                return float4(factor, other.g, col.b, other.a);
            #elif defined(FG_PACKED)
                UNITY_APPLY_FOG(i.fogCoord, col);
                return float4(col.r, i.fogCoord.y, i.fogCoord.z + i.fogCoord.w, i.fogCoord.x);
            #elif defined(FG_TBN)
                // A tangent frame that varies over the quad, the binormal mirrored (sign -1) in the
                // right half, packed as generated surface code packs it (fog in tSpace2.y), then
                // unpacked: the rows must come back.
                float3 n = normalize(float3(u - 0.5, v - 0.5, 1.0));
                float3 t = normalize(cross(float3(0.0, 1.0, 0.0), n));
                float3 b = cross(n, t) * (u < 0.5 ? 1.0 : -1.0);
                Interpolators j = i;
                j.tSpace0 = float4(t.x, b.x, n.x, 0.0);
                j.tSpace1 = float4(t.y, b.y, n.y, 0.0);
                j.tSpace2 = float4(t.z, b.z, n.z, 0.0);
                UNITY_TRANSFER_FOG_COMBINED_WITH_TSPACE(j, float4(0.0, 0.0, 0.0, 5.0));
                UNITY_RECONSTRUCT_TBN(j);
                // The interpolated members are all 0 here; reading them keeps them consumed.
                float unused = i.tSpace0.x + i.tSpace1.x + i.tSpace2.x + i.worldPos.x + i.eyeVec.x;
                return float4(_unity_tbn_2.y + unused, _unity_tbn_0.y, _unity_tbn_1.z, _unity_tbn_2.x);
            #else // FG_COMBINED
                float4 r = float4(0, 0, 0, 0);
                { UNITY_EXTRACT_FOG_FROM_TSPACE(i); fixed4 c = col; UNITY_APPLY_FOG(_unity_fogCoord, c); r.x = c.r; }
                { UNITY_EXTRACT_FOG_FROM_WORLD_POS(i); fixed4 c = col; UNITY_APPLY_FOG(_unity_fogCoord, c); r.y = c.r; }
                { UNITY_EXTRACT_FOG_FROM_EYE_VEC(i); fixed4 c = col; UNITY_APPLY_FOG(_unity_fogCoord, c); r.z = c.r; }
                r.w = i.worldPos.x + i.eyeVec.z + i.tSpace2.x + i.tSpace0.x + i.tSpace1.x;
                return r;
            #endif
            }
            ENDCG
        }
    }
}
