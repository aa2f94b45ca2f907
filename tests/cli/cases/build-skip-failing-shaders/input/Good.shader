Shader "Test/Skip/Good" {
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile _ TINT
            float4 vert(float4 position : POSITION) : SV_POSITION { return position; }
            float4 frag() : SV_Target {
            #ifdef TINT
                return float4(1, 0, 0, 1);
            #else
                return float4(1, 1, 1, 1);
            #endif
            }
            ENDCG
        }
    }
}
