// SPDX-License-Identifier: Apache-2.0
// varc lighting library: the deferred light shader. Technique of seed 002 ("Rendering 15:
// Deferred Lights"), written for varc on the built-in UnityDeferredLibrary.cginc.
//   Pass 0, light pass: one draw per light (a full-screen quad for directional lights, the
//           light volume otherwise). Reads depth and the G-buffers of GBuffer.shader, evaluates
//           UNITY_BRDF_PBS for the light and adds it to the light buffer:
//           HDR (UNITY_HDR_ON): colour, Blend One One;
//           LDR: exp2(-colour), Blend DstColor Zero, so the buffer holds exp2(-sum of lights).
//           Keywords: multi_compile_lightpass (light type x shadow type) x (_ | UNITY_HDR_ON).
//   Pass 1, LDR decode: writes -log2(light buffer), i.e. the sum of the lights, for the pixels
//           marked by the G-buffer pass's stencil bits.
// _SrcBlend/_DstBlend and _StencilNonBackground are set by the runtime (docs/SHADER_ABI.md §4.9).
// Math: docs/LIGHTING.md §8.3.
Shader "varc/DeferredLight" {
    Properties {
        [HideInInspector] _SrcBlend ("Source blend factor", Float) = 1
        [HideInInspector] _DstBlend ("Destination blend factor", Float) = 1
        [HideInInspector] _StencilNonBackground ("Stencil bit of drawn pixels", Float) = 128
    }

    SubShader {
        Pass {
            Blend [_SrcBlend] [_DstBlend]
            ZWrite Off

            Stencil {
                Ref [_StencilNonBackground]
                ReadMask [_StencilNonBackground]
                Comp Equal
            }

            CGPROGRAM
            #pragma target 3.0
            #pragma exclude_renderers nomrt
            #pragma multi_compile_lightpass
            #pragma multi_compile _ UNITY_HDR_ON
            #pragma vertex vert_deferred
            #pragma fragment DeferredLightFragment

            #include "UnityDeferredLibrary.cginc"
            #include "UnityPBSLighting.cginc"

            sampler2D _CameraGBufferTexture0;   // rgb diffuse colour, a occlusion
            sampler2D _CameraGBufferTexture1;   // rgb specular colour, a smoothness
            sampler2D _CameraGBufferTexture2;   // rgb world normal * 0.5 + 0.5

            float4 DeferredLightFragment(unity_v2f_deferred i) : SV_Target {
                float3 worldPos;
                float2 uv;
                half3 lightDir;
                float atten;
                float fadeDist;
                UnityDeferredCalculateLightParams(i, worldPos, uv, lightDir, atten, fadeDist);

                float4 diffuseOcclusion = tex2D(_CameraGBufferTexture0, uv);
                float4 specularSmoothness = tex2D(_CameraGBufferTexture1, uv);
                float3 normal = normalize(tex2D(_CameraGBufferTexture2, uv).rgb * 2 - 1);
                float3 viewDir = normalize(_WorldSpaceCameraPos - worldPos);
                half oneMinusReflectivity = 1 - SpecularStrength(specularSmoothness.rgb);

                UnityLight light;
                light.dir = lightDir;
                light.color = _LightColor.rgb * atten;
                light.ndotl = saturate(dot(normal, lightDir));
                UnityIndirect noIndirect;
                noIndirect.diffuse = 0;
                noIndirect.specular = 0;

                float4 colour = UNITY_BRDF_PBS(diffuseOcclusion.rgb, specularSmoothness.rgb, oneMinusReflectivity,
                                               specularSmoothness.a, normal, viewDir, light, noIndirect);
                // Alpha 0 leaves the light buffer's alpha unchanged: +0 (HDR), *exp2(-0) = *1 (LDR).
                colour.a = 0;
            #if !defined(UNITY_HDR_ON)
                colour = exp2(-colour);
            #endif
                return colour;
            }
            ENDCG
        }

        Pass {
            Cull Off
            ZTest Always
            ZWrite Off

            Stencil {
                Ref [_StencilNonBackground]
                ReadMask [_StencilNonBackground]
                CompBack Equal
                CompFront Equal
            }

            CGPROGRAM
            #pragma target 3.0
            #pragma exclude_renderers nomrt
            #pragma vertex DecodeVertex
            #pragma fragment DecodeFragment

            #include "UnityCG.cginc"

            sampler2D _LightBuffer;   // the LDR light buffer, exp2(-light)

            struct DecodeAttributes {
                float4 vertex : POSITION;
                float2 texcoord : TEXCOORD0;
            };

            struct DecodeVaryings {
                float4 pos : SV_POSITION;
                float2 uv : TEXCOORD0;
            };

            DecodeVaryings DecodeVertex(DecodeAttributes v) {
                DecodeVaryings o;
                o.pos = UnityObjectToClipPos(v.vertex);
                o.uv = v.texcoord;
                return o;
            }

            float4 DecodeFragment(DecodeVaryings i) : SV_Target {
                return -log2(tex2D(_LightBuffer, i.uv));
            }
            ENDCG
        }
    }
}
