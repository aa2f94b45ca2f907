// SPDX-License-Identifier: Apache-2.0
// A deferred light pass in the style of Unity's Internal-DeferredShading shader (our own text):
// reads the G-buffer through UnityGBuffer.cginc, the light through UnityDeferredLibrary.cginc
// (with the baked shadowmask of the fifth target), and lights it with a BRDF; a second pass
// picks the cheaper BRDF tiers by redefining UNITY_BRDF_PBS as lower-end shaders do.
// builtin.standard-passes builds every variant.
Shader "varc-tests/DeferredLightingLike" {
    Properties {
        _LightTexture0 ("", any) = "" {}
        _LightTextureB0 ("", 2D) = "" {}
        _ShadowMapTexture ("", any) = "" {}
        _SrcBlend ("", Float) = 1
        _DstBlend ("", Float) = 1
    }
    SubShader {
        Pass {
            ZWrite Off
            Blend [_SrcBlend] [_DstBlend]

            CGPROGRAM
            #pragma target 3.0
            #pragma vertex vert_deferred
            #pragma fragment frag
            #pragma multi_compile_lightpass
            #pragma multi_compile ___ UNITY_HDR_ON
            #pragma exclude_renderers nomrt
            #include "UnityCG.cginc"
            #include "UnityDeferredLibrary.cginc"
            #include "UnityPBSLighting.cginc"
            #include "UnityStandardUtils.cginc"
            #include "UnityGBuffer.cginc"
            #include "UnityStandardBRDF.cginc"

            sampler2D _CameraGBufferTexture0;
            sampler2D _CameraGBufferTexture1;
            sampler2D _CameraGBufferTexture2;

            half4 CalculateLight(unity_v2f_deferred i) {
                float3 wpos;
                float2 uv;
                float atten, fadeDist;
                UnityLight light;
                UNITY_INITIALIZE_OUTPUT(UnityLight, light);
                UnityDeferredCalculateLightParams(i, wpos, uv, light.dir, atten, fadeDist);
                atten *= UnityDeferredSampleShadowMask(uv);
                light.color = _LightColor.rgb * atten;
                half4 gbuffer0 = tex2D(_CameraGBufferTexture0, uv);
                half4 gbuffer1 = tex2D(_CameraGBufferTexture1, uv);
                half4 gbuffer2 = tex2D(_CameraGBufferTexture2, uv);
                UnityStandardData data = UnityStandardDataFromGbuffer(gbuffer0, gbuffer1, gbuffer2);
                float3 eyeVec = normalize(wpos - _WorldSpaceCameraPos);
                half oneMinusReflectivity = 1 - SpecularStrength(data.specularColor.rgb);
                UnityIndirect ind;
                UNITY_INITIALIZE_OUTPUT(UnityIndirect, ind);
                ind.diffuse = 0;
                ind.specular = 0;
                return UNITY_BRDF_PBS(data.diffuseColor, data.specularColor, oneMinusReflectivity, data.smoothness,
                                      data.normalWorld, -eyeVec, light, ind);
            }

            #ifdef UNITY_HDR_ON
            half4
            #else
            fixed4
            #endif
            frag(unity_v2f_deferred i) : SV_Target {
                half4 c = CalculateLight(i);
                #ifdef UNITY_HDR_ON
                return c;
                #else
                return exp2(-c);
                #endif
            }
            ENDCG
        }

        Pass {
            ZWrite Off
            Blend One One

            CGPROGRAM
            #pragma target 3.0
            #pragma vertex vert_deferred
            #pragma fragment frag
            #pragma multi_compile_lightpass
            #pragma multi_compile UNITY_PBS_USE_BRDF2 UNITY_PBS_USE_BRDF3
            #pragma skip_variants SHADOWS_SOFT SHADOWS_SHADOWMASK POINT_COOKIE DIRECTIONAL_COOKIE
            #if defined(UNITY_PBS_USE_BRDF2)
                #define UNITY_BRDF_PBS BRDF2_Unity_PBS
            #else
                #define UNITY_BRDF_PBS BRDF3_Unity_PBS
            #endif
            #include "UnityCG.cginc"
            #include "UnityDeferredLibrary.cginc"
            #include "UnityPBSLighting.cginc"
            #include "UnityGBuffer.cginc"

            sampler2D _CameraGBufferTexture0;
            sampler2D _CameraGBufferTexture1;
            sampler2D _CameraGBufferTexture2;

            half4 frag(unity_v2f_deferred i) : SV_Target {
                float3 wpos;
                float2 uv;
                float atten, fadeDist;
                UnityLight light;
                UNITY_INITIALIZE_OUTPUT(UnityLight, light);
                UnityDeferredCalculateLightParams(i, wpos, uv, light.dir, atten, fadeDist);
                light.color = _LightColor.rgb * atten;
                UnityStandardData data = UnityStandardDataFromGbuffer(tex2D(_CameraGBufferTexture0, uv),
                    tex2D(_CameraGBufferTexture1, uv), tex2D(_CameraGBufferTexture2, uv));
                half4 g0 = half4(data.diffuseColor, data.occlusion);
                half4 g1 = half4(data.specularColor, data.smoothness);
                half4 g2 = half4(data.normalWorld * 0.5 + 0.5, 1);
                UnityStandardDataApplyWeightToGbuffer(g0, g1, g2, 0.5);
                UnityIndirect ind = (UnityIndirect)0;
                half3 v = normalize(_WorldSpaceCameraPos - wpos);
                return UNITY_BRDF_PBS(g0.rgb, g1.rgb, 0.9, g1.a, data.normalWorld, v, light, ind)
                     + half4(BRDF_Unity_Indirect(g0.rgb, g1.rgb, 0.9, g1.a, data.normalWorld, v, 1, (UnityGI)0), 0);
            }
            ENDCG
        }
    }
    Fallback Off
}
