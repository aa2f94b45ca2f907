Shader "Test/Skip/CompileError" {
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile _ BROKEN
            float4 vert(float4 position : POSITION) : SV_POSITION { return position; }
            float4 frag() : SV_Target {
            #ifdef BROKEN
                return undeclaredColour;
            #else
                return float4(0, 0, 0, 1);
            #endif
            }
            ENDCG
        }
    }
}
