// SPDX-License-Identifier: Apache-2.0
// Property validation (issue #16): a shader with both render paths, for the relation
// forward_deferred. Its Deferred pass is the library's G-buffer pass (UsePass), its ForwardBase
// and ForwardAdd passes shade each light with the BRDF varc/DeferredLight applies to that
// G-buffer (ForwardDeferredLighting.cginc), so forward and deferred renders agree; it holds
// every relation.
Shader "varc-tests/ForwardDeferred" {
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
            #include "ForwardDeferredLighting.cginc"
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
            #include "ForwardDeferredLighting.cginc"
            ENDCG
        }

        UsePass "varc/DeferredGBuffer/DEFERRED"
    }
    Fallback "Legacy Shaders/VertexLit"
}
