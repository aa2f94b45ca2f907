// SPDX-License-Identifier: Apache-2.0
// Property classification fixture (issues #16, #29): a ForwardBase pass that draws half its
// albedo and reads no light input, and no ForwardAdd pass: not lit, proven by the reflection.
Shader "varc-mutants/Unlit" {
    Properties {
        _Color ("Albedo colour", Color) = (1, 1, 1, 1)
        _MainTex ("Albedo (RGB)", 2D) = "white" {}
    }

    SubShader {
        Tags { "RenderType" = "Opaque" }

        Pass {
            Tags { "LightMode" = "ForwardBase" }

            CGPROGRAM
            #pragma vertex UnlitVertex
            #pragma fragment UnlitFragment
            #include "UnlitProgram.cginc"
            ENDCG
        }
    }
}
