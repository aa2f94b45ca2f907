// Always included by Graphics Settings: every declared variant ships.
Shader "Hidden/TestBlit" {
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma shader_feature _ _FLIP
            float4 vert(float4 position : POSITION) : SV_POSITION { return position; }
            float4 frag() : SV_Target {
            #ifdef _FLIP
                return 1;
            #else
                return 0;
            #endif
            }
            ENDCG
        }
    }
}
