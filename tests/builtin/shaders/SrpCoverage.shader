// SPDX-License-Identifier: Apache-2.0
// Test shader for tests/builtin (compile_fixtures.sh): an HLSLPROGRAM on the SRP core subset
// (Common.hlsl, UnityInstancing.hlsl) with separate textures/samplers and instanced properties.
Shader "varc-test/SrpCoverage" {
    Properties {
        _BaseColor ("Color", Color) = (1, 1, 1, 1)
        _BaseMap ("Albedo", 2D) = "white" {}
    }
    SubShader {
        Pass {
            HLSLPROGRAM
            #pragma target 3.5
            #pragma multi_compile_instancing
            #pragma vertex vert
            #pragma fragment frag
            #include "Packages/com.unity.render-pipelines.core/ShaderLibrary/Common.hlsl"

            CBUFFER_START(UnityPerFrame)
                float4x4 unity_MatrixVP;
            CBUFFER_END
            CBUFFER_START(UnityPerDraw)
                float4x4 unity_ObjectToWorld;
                float4x4 unity_WorldToObject;
            CBUFFER_END
            #define UNITY_MATRIX_M unity_ObjectToWorld
            #define UNITY_MATRIX_I_M unity_WorldToObject
            #include "Packages/com.unity.render-pipelines.core/ShaderLibrary/UnityInstancing.hlsl"

            TEXTURE2D(_BaseMap);
            SAMPLER(sampler_BaseMap);
            UNITY_INSTANCING_BUFFER_START(PerInstance)
                UNITY_DEFINE_INSTANCED_PROP(float4, _BaseColor)
                UNITY_DEFINE_INSTANCED_PROP(float, _Cutoff)
            UNITY_INSTANCING_BUFFER_END(PerInstance)

            struct Attributes {
                float4 positionOS : POSITION;
                float3 normalOS : NORMAL;
                float2 uv : TEXCOORD0;
                UNITY_VERTEX_INPUT_INSTANCE_ID
            };
            struct Varyings {
                float4 positionCS : SV_POSITION;
                float3 normalWS : TEXCOORD0;
                float2 uv : TEXCOORD1;
                UNITY_VERTEX_INPUT_INSTANCE_ID
            };

            Varyings vert(Attributes input) {
                Varyings output;
                UNITY_SETUP_INSTANCE_ID(input);
                UNITY_TRANSFER_INSTANCE_ID(input, output);
                output.positionCS = mul(unity_MatrixVP, mul(UNITY_MATRIX_M, float4(input.positionOS.xyz, 1.0)));
                output.normalWS = SafeNormalize(mul(input.normalOS, (float3x3)UNITY_MATRIX_I_M));
                output.uv = input.uv;
                return output;
            }
            float4 frag(Varyings input) : SV_TARGET {
                UNITY_SETUP_INSTANCE_ID(input);
                real4 base = SAMPLE_TEXTURE2D(_BaseMap, sampler_BaseMap, input.uv)
                           * UNITY_ACCESS_INSTANCED_PROP(PerInstance, _BaseColor);
                clip(base.a - UNITY_ACCESS_INSTANCED_PROP(PerInstance, _Cutoff));
                float ndotl = saturate(dot(normalize(input.normalWS), float3(0, 1, 0)));
                return float4(base.rgb * (ndotl + INV_PI * Sq(0.1)), 1);
            }
            ENDHLSL
        }
    }
}
