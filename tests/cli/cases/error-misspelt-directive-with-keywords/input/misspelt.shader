Shader "Test/Misspelt" {
    SubShader {
        Pass {
            CGPROGRAM
            #pragma multi_compile_fragmnt _ _GLOW
            ENDCG
        }
    }
}
