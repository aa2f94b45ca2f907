// SPDX-License-Identifier: Apache-2.0
// Property mutation test (issue #16): a copy of tests/properties/shaders/ForwardDeferred.shader
// whose forward passes shade with Lambert diffuse and no specular while its Deferred pass (the
// library's G-buffer, lit by varc/DeferredLight) keeps the Standard BRDF: the two paths draw
// different images, which only forward_deferred sees (each path alone is a correct light).
Shader "varc-mutants/LambertForward" {
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
            Tags { "LightMode" = "ForwardBase" }

            CGPROGRAM
            #pragma target 3.0
            #pragma vertex BothPathsVertex
            #pragma fragment BothPathsFragment
            #define VARC_BOTH_PATHS_BASE 1
            #define MUTANT_LAMBERT_FORWARD 1
            #include "../shaders/ForwardDeferredLighting.cginc"
            ENDCG
        }

        Pass {
            Tags { "LightMode" = "ForwardAdd" }
            Blend One One
            ZWrite Off

            CGPROGRAM
            #pragma target 3.0
            #pragma multi_compile_fwdadd_fullshadows
            #pragma vertex BothPathsVertex
            #pragma fragment BothPathsFragment
            #define MUTANT_LAMBERT_FORWARD 1
            #include "../shaders/ForwardDeferredLighting.cginc"
            ENDCG
        }

        UsePass "varc/DeferredGBuffer/DEFERRED"
    }
    Fallback "Legacy Shaders/VertexLit"
}
