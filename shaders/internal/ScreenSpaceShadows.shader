// SPDX-License-Identifier: Apache-2.0
// varc's screen-space shadow collector: for a directional light with shadows, turns the camera's
// depth and the light's cascaded shadow map into a screen-sized mask the lit passes read
// (SHADOWS_SCREEN: `_ShadowMapTexture.r` at the pixel, 1 = lit, strength applied, no fade).
// The runtime draws it as a full-screen quad (docs/SHADER_ABI.md §4.7, docs/LIGHTING.md §6).
//   Cascade selection: close fit by the view depth against _LightSplitsNear/_LightSplitsFar;
//   stable fit (SHADOWS_SPLIT_SPHERES) by the split spheres, the first one that holds the point;
//   SHADOWS_SINGLE_CASCADE reads unity_WorldToShadow[0] only. No cascade: lit.
//   Hard: one comparison at the nearest texel. Soft (SHADOWS_SOFT): the 7 x 7 tent filter, each
//   atlas texel weighted by the area the tent, 7 texels wide and centred on the coordinate,
//   covers of it (what Unity's 16 bilinear comparisons add up to).
// Written for varc.
Shader "Hidden/varc/ScreenSpaceShadows" {
    SubShader {
        Pass {
            ZTest Always ZWrite Off Cull Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile_shadowcollector
            #pragma multi_compile _ SHADOWS_SOFT
            #include "UnityCG.cginc"
            #include "UnityShadowLibrary.cginc"

            sampler2D_float _CameraDepthTexture;
            sampler2D_float _ShadowMapTexture;  // the cascade atlas, Vulkan depth
            float4 _ShadowMapTexture_TexelSize;
            float4x4 varc_CameraInvViewProjection;

            struct v2f {
                float4 pos : SV_POSITION;
            };

            v2f vert(float4 vertex : POSITION) {
                v2f o;
                o.pos = UnityObjectToClipPos(vertex);
                return o;
            }

            // Which cascade holds |wpos| (one weight 1, or none).
            float4 cascadeWeights(float3 wpos, float viewZ) {
            #if defined(SHADOWS_SPLIT_SPHERES)
                float3 c0 = wpos - unity_ShadowSplitSpheres[0].xyz;
                float3 c1 = wpos - unity_ShadowSplitSpheres[1].xyz;
                float3 c2 = wpos - unity_ShadowSplitSpheres[2].xyz;
                float3 c3 = wpos - unity_ShadowSplitSpheres[3].xyz;
                float4 distances2 = float4(dot(c0, c0), dot(c1, c1), dot(c2, c2), dot(c3, c3));
                float4 weights = float4(distances2 < unity_ShadowSplitSqRadii);
                weights.yzw = saturate(weights.yzw - weights.xyz);
                return weights;
            #else
                return float4(viewZ >= _LightSplitsNear) * float4(viewZ < _LightSplitsFar);
            #endif
            }

            float3 shadowCoord(float3 wpos, float viewZ) {
            #if defined(SHADOWS_SINGLE_CASCADE)
                return mul(unity_WorldToShadow[0], float4(wpos, 1)).xyz;
            #else
                float4 weights = cascadeWeights(wpos, viewZ);
                return weights.x * mul(unity_WorldToShadow[0], float4(wpos, 1)).xyz
                     + weights.y * mul(unity_WorldToShadow[1], float4(wpos, 1)).xyz
                     + weights.z * mul(unity_WorldToShadow[2], float4(wpos, 1)).xyz
                     + weights.w * mul(unity_WorldToShadow[3], float4(wpos, 1)).xyz;
            #endif
            }

            float texelLit(float2 texel, float depth) {
                float2 uv = (texel + 0.5) * _ShadowMapTexture_TexelSize.xy;
                return depth <= tex2Dlod(_ShadowMapTexture, float4(uv, 0, 0)).r ? 1.0 : 0.0;
            }

            float litAt(float3 coord) {
                float2 position = coord.xy * _ShadowMapTexture_TexelSize.zw;
            #if defined(SHADOWS_SOFT)
                float2 centre = floor(position + 0.5);  // the texel corner nearest the centre
                float2 offset = position - centre;      // in [-0.5, 0.5]
                float lit = 0.0;
                for (int j = -4; j < 4; ++j) {
                    float wy = UnityShadowTentArea(j + 1 - offset.y, 3.5)
                             - UnityShadowTentArea(j - offset.y, 3.5);
                    for (int i = -4; i < 4; ++i) {
                        float wx = UnityShadowTentArea(i + 1 - offset.x, 3.5)
                                 - UnityShadowTentArea(i - offset.x, 3.5);
                        lit += wx * wy * texelLit(centre + float2(i, j), coord.z);
                    }
                }
                return lit;
            #else
                return texelLit(floor(position), coord.z);
            #endif
            }

            float4 frag(v2f i) : SV_Target {
                float2 uv = i.pos.xy * (_ScreenParams.zw - 1.0);
                float depth = tex2Dlod(_CameraDepthTexture, float4(uv, 0, 0)).r;
                float4 world = mul(varc_CameraInvViewProjection, float4(uv * 2.0 - 1.0, depth, 1.0));
                float3 wpos = world.xyz / world.w;
                float viewZ = dot(_WorldSpaceCameraPos.xyz - wpos, UNITY_MATRIX_V[2].xyz);
                float shadow = lerp(_LightShadowData.r, 1.0, litAt(shadowCoord(wpos, viewZ)));
                return float4(shadow, shadow, shadow, 1.0);
            }
            ENDCG
        }
    }
}
