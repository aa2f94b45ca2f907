Shader "Test/Cycle" {
    SubShader {
        Pass {
            CGPROGRAM
            #include "a.hlsl"
            ENDCG
        }
    }
}
