// Version 1 of a shader under a variant-count lock.
Shader "Test/Lit" {
    SubShader {
        Pass {
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma multi_compile _ VERTEXLIGHT_ON
            ENDCG
        }
        Pass {
            Tags { "LightMode" = "ForwardAdd" }
            Blend One One
            CGPROGRAM
            #pragma multi_compile_fwdadd
            ENDCG
        }
    }
}
