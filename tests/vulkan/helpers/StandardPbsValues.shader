// SPDX-License-Identifier: Apache-2.0
// Evaluates functions of the Standard-pipeline include files (UnityStandardBRDF, UnityGBuffer,
// UnityStandardInput, UnityStandardCore, UnityMetaPass) at every pixel of a full-target quad
// (pixel centre (u, v) as input, four floats per variant) for
// tests/vulkan/StandardPbsValueTest.cpp.
Shader "Test/StandardPbsValues" {
    SubShader {
        Pass {
            Cull Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile API_HSV API_BRDF3 API_BRDF2 API_GBUFFER_WEIGHT API_METALLIC_ROUGH API_IBL_DIR API_IBL_WEIGHT API_SUBTRACT API_DIRSPEC
            #include "UnityStandardCore.cginc"
            #include "UnityMetaPass.cginc"
            struct Interpolators {
                float4 pos : SV_POSITION;
                float2 uv : TEXCOORD0;
            };
            Interpolators vert(float4 vertex : POSITION, float2 uv : TEXCOORD0) {
                Interpolators i;
                i.pos = float4(vertex.xy, 0.5, 1.0);
                i.uv = uv;
                return i;
            }
            float4 frag(Interpolators i) : SV_Target {
                float u = i.uv.x, v = i.uv.y;
            #if defined(API_HSV)
                return float4(UnityMeta_RGBToHSV(half3(u, v, 0.5)), UnityMeta_RGBToHSVHelper(2, 1.1, u, v).x);
            #elif defined(API_BRDF3)
                UnityIndirect ind;
                ind.diffuse = half3(0.5, 0.2, 0.1);
                ind.specular = half3(v, 0.3, 0.6);
                half3 direct = BRDF3_Direct(half3(u, v, 0.2), half3(0.04 + 0.5 * v, 0.3, u), v, 0.1 + 0.5 * u);
                half3 indirect = BRDF3_Indirect(half3(u, v, 0.2), half3(0.04 + 0.5 * v, 0.3, u), ind, 0.7 * u, v);
                return float4(direct, indirect.x);
            #elif defined(API_BRDF2)
                UnityLight light;
                light.dir = normalize(half3(u - 0.5, v - 0.5, 1.0));
                light.color = half3(1.0, 0.8, 0.6);
                light.ndotl = 0;
                UnityIndirect gi;
                gi.diffuse = half3(0.1, 0.2, 0.3);
                gi.specular = half3(0.4, 0.5, 0.6);
                return BRDF2_Unity_PBS(half3(u, v, 0.2), half3(0.04 + 0.3 * v, 0.3, 0.2), 0.8, 0.2 + 0.7 * u,
                                       float3(0, 0, 1), normalize(float3(0.3, 0.2, 1.0)), light, gi);
            #elif defined(API_GBUFFER_WEIGHT)
                half4 g0 = half4(u, v, 0.3, 0.9), g1 = half4(0.2, u, v, 0.5), g2 = half4(v, 0.1, u, 1.0);
                UnityStandardDataApplyWeightToGbuffer(g0, g1, g2, 0.25 + 0.5 * u);
                return float4(g0.r, g0.a, g1.a, g2.b);
            #elif defined(API_SUBTRACT)
                half3 n = normalize(half3(u - 0.5, 0.3, 1.0));
                return float4(SubtractMainLightWithRealtimeAttenuationFromLightmap(half3(u, v, 0.5), v, 0, n), 0);
            #elif defined(API_DIRSPEC)
                UnityLight light;
                half3 rest = DecodeDirectionalSpecularLightmap(half3(u, v, 0.5), half4(u, v, 0.8, 1.0),
                                                               normalize(half3(0.2, 0.3, 1.0)), false, 0, light);
                return float4(rest.x, light.color.y, light.dir.x, light.ndotl);
            #elif defined(API_IBL_DIR) || defined(API_IBL_WEIGHT)
                float3 N = float3(0, 0, 1), tX = float3(1, 0, 0), tY = float3(0, 1, 0);
                float3 V = normalize(float3(0.2, 0.1, 1.0));
                #if defined(API_IBL_DIR)
                float3 H, L;
                ImportanceSampleGGXDir(float2(u, v), V, N, tX, tY, 0.5, H, L);
                return float4(L.x, L.y, H.z, Hash(uint(u * 64.0) * 64u + uint(v * 64.0)));
                #else
                float3 L, Lc;
                float VdotH, NdotL, w;
                ImportanceSampleGGX(float2(u, v), V, N, tX, tY, 0.5, dot(N, V), L, VdotH, NdotL, w);
                ImportanceSampleCosDir(float2(u, v), N, tX, tY, Lc);
                return float4(VdotH, NdotL, w, Lc.z);
                #endif
            #else
                half4 rows[3];
                rows[0] = half4(1, 0, 0, u);
                rows[1] = half4(0, 1, 0, v);
                rows[2] = half4(u - 0.5, v, 0.3, 0);
                half2 mr = MetallicRough(i.uv);
                return float4(mr.x * u, mr.y * v, NormalizePerPixelNormal(float3(u, v, 0.5)).x, WorldNormal(rows).y);
            #endif
            }
            ENDCG
        }
    }
}
