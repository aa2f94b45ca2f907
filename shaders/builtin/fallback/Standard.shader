// SPDX-License-Identifier: Apache-2.0
// varc built-in: "Standard" as a fallback, for its shadow caster (UnityStandardShadow.cginc):
// opaque, alpha-tested (_ALPHATEST_ON, clipped at _Cutoff) and alpha-blended materials
// (_ALPHABLEND_ON, _ALPHAPREMULTIPLY_ON). Soft shadows are a property of the receiver, so the
// caster skips SHADOWS_SOFT. Written for varc.
Shader "Standard" {
    Properties {
        _Color ("Color", Color) = (1, 1, 1, 1)
        _MainTex ("Albedo", 2D) = "white" {}
        _Cutoff ("Alpha Cutoff", Range(0, 1)) = 0.5
    }
    SubShader {
        Tags { "RenderType" = "Opaque" "PerformanceChecks" = "False" }
        Pass {
            Name "ShadowCaster"
            Tags { "LightMode" = "ShadowCaster" }
            ZWrite On ZTest LEqual
            CGPROGRAM
            #pragma target 3.0
            #pragma shader_feature_local _ _ALPHATEST_ON _ALPHABLEND_ON _ALPHAPREMULTIPLY_ON
            #pragma skip_variants SHADOWS_SOFT
            #pragma multi_compile_shadowcaster
            #pragma vertex vertShadowCaster
            #pragma fragment fragShadowCaster
            #include "UnityStandardShadow.cginc"
            ENDCG
        }
    }
}
