// SPDX-License-Identifier: Apache-2.0
// The Standard shader's forward passes built on the simple path: UNITY_STANDARD_SIMPLE 1 before
// UnityStandardCoreForward.cginc selects UnityStandardCoreForwardSimple.cginc, as Unity's low-end
// tier does. A subset of the Standard keywords (small, so the test stays fast); builtin.textcore-glsl
// builds every variant. Written for varc's tests.
Shader "varc-tests/StandardSimple" {
    Properties {
        _Color ("Colour", Color) = (1, 1, 1, 1)
        _MainTex ("Albedo", 2D) = "white" {}
        _Cutoff ("Alpha cutoff", Range(0, 1)) = 0.5
        _Glossiness ("Smoothness", Range(0, 1)) = 0.5
        [Gamma] _Metallic ("Metallic", Range(0, 1)) = 0
        _MetallicGlossMap ("Metallic", 2D) = "white" {}
        _BumpScale ("Normal scale", Float) = 1
        _BumpMap ("Normal map", 2D) = "bump" {}
        _EmissionColor ("Emission colour", Color) = (0, 0, 0)
        _EmissionMap ("Emission", 2D) = "white" {}
        [HideInInspector] _SrcBlend ("", Float) = 1
        [HideInInspector] _DstBlend ("", Float) = 0
        [HideInInspector] _ZWrite ("", Float) = 1
    }

    SubShader {
        Tags { "RenderType" = "Opaque" "PerformanceChecks" = "False" }
        LOD 150

        Pass {
            Name "FORWARD"
            Tags { "LightMode" = "ForwardBase" }
            Blend [_SrcBlend] [_DstBlend]
            ZWrite [_ZWrite]

            CGPROGRAM
            #pragma target 2.0
            #pragma shader_feature_local _NORMALMAP
            #pragma shader_feature_local _SPECULARHIGHLIGHTS_OFF
            #pragma shader_feature_local _ _METALLICGLOSSMAP _ALPHATEST_ON _EMISSION
            #pragma multi_compile_fwdbase
            #pragma skip_variants DYNAMICLIGHTMAP_ON LIGHTMAP_SHADOW_MIXING SHADOWS_SHADOWMASK DIRLIGHTMAP_COMBINED VERTEXLIGHT_ON LIGHTPROBE_SH
            #pragma multi_compile __ FOG_LINEAR
            #pragma vertex vertBase
            #pragma fragment fragBase
            #define UNITY_STANDARD_SIMPLE 1
            #define UNITY_SETUP_BRDF_INPUT MetallicSetup
            #include "UnityStandardCoreForward.cginc"
            ENDCG
        }

        Pass {
            Name "FORWARD_DELTA"
            Tags { "LightMode" = "ForwardAdd" }
            Blend [_SrcBlend] One
            Fog { Color (0, 0, 0, 0) }
            ZWrite Off
            ZTest LEqual

            CGPROGRAM
            #pragma target 2.0
            #pragma shader_feature_local _NORMALMAP
            #pragma shader_feature_local _SPECULARHIGHLIGHTS_OFF
            #pragma shader_feature_local _ _ALPHABLEND_ON
            #pragma multi_compile POINT SPOT DIRECTIONAL
            #pragma multi_compile __ FOG_LINEAR
            #pragma vertex vertAdd
            #pragma fragment fragAdd
            #define UNITY_STANDARD_SIMPLE 1
            #define UNITY_SETUP_BRDF_INPUT MetallicSetup
            #include "UnityStandardCoreForward.cginc"
            ENDCG
        }
    }
}
