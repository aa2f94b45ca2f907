Shader "Test/Unterminated" {
    SubShader {
        Pass {
            HLSLPROGRAM
            #pragma vertex vert
            float4 vert() : SV_Position { return 0; }
        }
    }
}
