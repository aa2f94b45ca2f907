// SPDX-License-Identifier: Apache-2.0
// varc lighting library: the G-buffer pass of deferred shading (LightMode Deferred), metallic
// workflow. Technique of seed 002 ("Rendering 15: Deferred Lights"), written for varc; the light
// pass that reads these targets is DeferredLight.shader. Four render targets
// (docs/SHADER_ABI.md §6):
//   SV_Target0  rgb = diffuse colour, a = occlusion (1)
//   SV_Target1  rgb = specular colour, a = smoothness
//   SV_Target2  rgb = world normal * 0.5 + 0.5, a = 1
//   SV_Target3  emission + ambient (diffuse * ShadeSH9): linear with UNITY_HDR_ON, else exp2(-c)
//               (the LDR light buffer, multiplied into by the light pass with Blend DstColor Zero)
// Every drawn pixel gets the _StencilNonBackground bits, so the light pass and the LDR decode
// skip the background. Math: docs/LIGHTING.md §8.3.
Shader "varc/DeferredGBuffer" {
    Properties {
        _Color ("Albedo colour", Color) = (1, 1, 1, 1)
        _MainTex ("Albedo (RGB)", 2D) = "white" {}
        _Metallic ("Metallic", Range(0, 1)) = 0
        _Smoothness ("Smoothness", Range(0, 1)) = 0.5
        _EmissionColor ("Emission", Color) = (0, 0, 0, 1)
        [HideInInspector] _StencilNonBackground ("Stencil bit of drawn pixels", Float) = 128
    }

    SubShader {
        Tags { "RenderType" = "Opaque" }

        Pass {
            // Shaders with both paths take this pass with UsePass "varc/DeferredGBuffer/DEFERRED"
            // (tests/properties/shaders/ForwardDeferred.shader).
            Name "DEFERRED"
            Tags { "LightMode" = "Deferred" }

            Stencil {
                Ref [_StencilNonBackground]
                WriteMask [_StencilNonBackground]
                Comp Always
                Pass Replace
            }

            CGPROGRAM
            #pragma target 3.0
            #pragma exclude_renderers nomrt
            #pragma multi_compile _ UNITY_HDR_ON
            #pragma vertex GBufferVertex
            #pragma fragment GBufferFragment

            #include "UnityPBSLighting.cginc"

            float4 _Color;
            sampler2D _MainTex;
            float4 _MainTex_ST;
            float _Metallic;
            float _Smoothness;
            float4 _EmissionColor;

            struct GBufferAttributes {
                float4 vertex : POSITION;
                float3 normal : NORMAL;
                float2 texcoord : TEXCOORD0;
            };

            struct GBufferVaryings {
                float4 pos : SV_POSITION;
                float2 uv : TEXCOORD0;
                float3 worldNormal : TEXCOORD1;
            };

            struct GBufferTargets {
                float4 diffuseOcclusion : SV_Target0;
                float4 specularSmoothness : SV_Target1;
                float4 normal : SV_Target2;
                float4 emissionAmbient : SV_Target3;
            };

            GBufferVaryings GBufferVertex(GBufferAttributes v) {
                GBufferVaryings o;
                o.pos = UnityObjectToClipPos(v.vertex);
                o.uv = TRANSFORM_TEX(v.texcoord, _MainTex);
                o.worldNormal = UnityObjectToWorldNormal(v.normal);
                return o;
            }

            GBufferTargets GBufferFragment(GBufferVaryings i) {
                float3 normal = normalize(i.worldNormal);
                float3 albedo = tex2D(_MainTex, i.uv).rgb * _Color.rgb;
                half3 specColor;
                half oneMinusReflectivity;
                half3 diffColor = DiffuseAndSpecularFromMetallic(albedo, _Metallic, specColor, oneMinusReflectivity);

                GBufferTargets o;
                o.diffuseOcclusion = float4(diffColor, 1);
                o.specularSmoothness = float4(specColor, _Smoothness);
                o.normal = float4(normal * 0.5 + 0.5, 1);
                float3 light = _EmissionColor.rgb + diffColor * max(0, ShadeSH9(float4(normal, 1)));
            #if !defined(UNITY_HDR_ON)
                light = exp2(-light);
            #endif
                o.emissionAmbient = float4(light, 1);
                return o;
            }
            ENDCG
        }
    }
    // Shadows are cast by the fallback's caster (shaders/builtin/fallback/VertexLit.shader).
    Fallback "Legacy Shaders/VertexLit"
}
