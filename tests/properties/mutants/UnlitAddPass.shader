// SPDX-License-Identifier: Apache-2.0
// Property mutation test (issue #29): varc-mutants/Unlit with a ForwardAdd pass that reads no
// light input. Unity draws that pass once per light for nothing: `lit` must FAIL on the finding.
Shader "varc-mutants/UnlitAddPass" {
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

        Pass {
            Tags { "LightMode" = "ForwardAdd" }
            Blend One One
            ZWrite Off

            CGPROGRAM
            #pragma multi_compile_fwdadd
            #pragma vertex UnlitVertex
            #pragma fragment UnlitFragment
            #define UNLIT_NOTHING 1
            #include "UnlitProgram.cginc"
            ENDCG
        }
    }
}
