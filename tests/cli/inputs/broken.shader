// A fragment program with a type error in one variant only.
Shader "Test/Broken" {
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile _ BROKEN
            float4 vert(float4 position : POSITION) : SV_POSITION { return position; }
            float4 frag() : SV_Target {
            #ifdef BROKEN
                return undefined_symbol;
            #else
                return float4(1, 1, 1, 1);
            #endif
            }
            ENDCG
        }
    }
}
