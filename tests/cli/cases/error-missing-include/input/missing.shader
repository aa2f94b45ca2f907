Shader "Test/MissingInclude" {
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Helpers.cginc"
            ENDCG
        }
    }
}
