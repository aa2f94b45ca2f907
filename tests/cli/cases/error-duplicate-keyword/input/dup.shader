Shader "Test/Duplicate" {
    SubShader {
        Pass {
            CGPROGRAM
            #pragma multi_compile _ FOG_ON LIGHT_ON FOG_ON
            ENDCG
        }
    }
}
