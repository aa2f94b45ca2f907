// SPDX-License-Identifier: Apache-2.0
// Test shader for tests/builtin (compile_fixtures.sh): forward base/add, shadow caster and a
// deferred light pass written against varc's built-in include library.
Shader "varc-test/LibraryCoverage" {
    Properties {
        _Color ("Color", Color) = (1, 1, 1, 1)
        _MainTex ("Albedo", 2D) = "white" {}
        _BumpMap ("Normal", 2D) = "bump" {}
        _Metallic ("Metallic", Range(0, 1)) = 0
        _Glossiness ("Smoothness", Range(0, 1)) = 0.5
    }
    SubShader {
        Pass {
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma target 3.5
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile_fwdbase
            #pragma multi_compile_fog
            #pragma multi_compile_instancing
            #include "LibraryCoverage.cginc"
            ENDCG
        }
        Pass {
            Tags { "LightMode" = "ForwardAdd" }
            Blend One One
            ZWrite Off
            CGPROGRAM
            #pragma target 3.0
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile_fwdadd_fullshadows
            #pragma multi_compile_fog
            #include "LibraryCoverage.cginc"
            ENDCG
        }
        Pass {
            Tags { "LightMode" = "ShadowCaster" }
            CGPROGRAM
            #pragma target 3.0
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile_shadowcaster
            #include "UnityCG.cginc"
            struct v2f { V2F_SHADOW_CASTER; };
            v2f vert(appdata_base v) {
                v2f o;
                TRANSFER_SHADOW_CASTER_NORMALOFFSET(o)
                return o;
            }
            float4 frag(v2f i) : SV_Target {
                SHADOW_CASTER_FRAGMENT(i)
            }
            ENDCG
        }
        Pass {
            ZWrite Off
            Blend [_SrcBlend] [_DstBlend]
            CGPROGRAM
            #pragma target 3.0
            #pragma vertex vert_deferred
            #pragma fragment frag
            #pragma multi_compile_lightpass
            #pragma multi_compile _ UNITY_HDR_ON
            #include "UnityPBSLighting.cginc"
            #include "UnityDeferredLibrary.cginc"
            sampler2D _CameraGBufferTexture0;
            sampler2D _CameraGBufferTexture1;
            sampler2D _CameraGBufferTexture2;
            half4 frag(unity_v2f_deferred i) : SV_Target {
                float3 wpos;
                float2 uv;
                half3 lightDir;
                float atten;
                float fadeDist;
                UnityDeferredCalculateLightParams(i, wpos, uv, lightDir, atten, fadeDist);
                half4 gbuffer0 = tex2D(_CameraGBufferTexture0, uv);
                half4 gbuffer1 = tex2D(_CameraGBufferTexture1, uv);
                half3 normal = normalize(tex2D(_CameraGBufferTexture2, uv).rgb * 2 - 1);
                UnityLight light;
                light.color = _LightColor.rgb * atten;
                light.dir = lightDir;
                light.ndotl = 0;
                UnityIndirect ind;
                ind.diffuse = 0;
                ind.specular = 0;
                half oneMinusReflectivity = 1 - SpecularStrength(gbuffer1.rgb);
                half4 c = UNITY_BRDF_PBS(gbuffer0.rgb, gbuffer1.rgb, oneMinusReflectivity, gbuffer1.a,
                                         normal, normalize(_WorldSpaceCameraPos - wpos), light, ind);
            #if !defined(UNITY_HDR_ON)
                c = exp2(-c);
            #endif
                return c;
            }
            ENDCG
        }
    }
}
