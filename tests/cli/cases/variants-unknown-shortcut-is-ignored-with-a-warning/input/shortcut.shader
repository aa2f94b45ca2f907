Shader "Test/Shortcut" {
    SubShader {
        Pass {
            Tags { "LightMode" = "ForwardAdd" }
            CGPROGRAM
            #pragma multi_compile_fwdadd_fullshadow
            ENDCG
        }
    }
}
