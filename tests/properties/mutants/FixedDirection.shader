// SPDX-License-Identifier: Apache-2.0
// Property mutation test (issue #29): a copy of shaders/forward/Forward.shader. Every light
// shines from straight above, wherever it is: a fixed light direction, which the relations that
// move or turn the scene about the y axis cannot see.
Shader "varc-mutants/FixedDirection" {
    Properties {
        _Color ("Albedo colour", Color) = (1, 1, 1, 1)
        _MainTex ("Albedo (RGB)", 2D) = "white" {}
        _Metallic ("Metallic", Range(0, 1)) = 0
        _Smoothness ("Smoothness", Range(0, 1)) = 0.5
    }

    SubShader {
        Tags { "RenderType" = "Opaque" }

        Pass {
            Tags { "LightMode" = "ForwardBase" }

            CGPROGRAM
            #pragma target 3.0
            #pragma multi_compile _ VERTEXLIGHT_ON
            #pragma vertex ForwardVertex
            #pragma fragment ForwardFragment
            #define VARC_FORWARD_BASE 1
            #define MUTANT_FIXED_DIRECTION 1
            #include "MutantLighting.cginc"
            ENDCG
        }

        Pass {
            Tags { "LightMode" = "ForwardAdd" }
            Blend One One
            ZWrite Off

            CGPROGRAM
            #pragma target 3.0
            #pragma multi_compile_fwdadd_fullshadows
            #pragma vertex ForwardVertex
            #pragma fragment ForwardFragment
            #define MUTANT_FIXED_DIRECTION 1
            #include "MutantLighting.cginc"
            ENDCG
        }
    }
    Fallback "Legacy Shaders/VertexLit"
}
