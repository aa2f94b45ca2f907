// Two keywords, each read by one stage only: 4 variants but 2 vertex and 2 fragment programs.
Shader "Test/TwoStageKeywords" {
    SubShader {
        Pass {
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile _ WOBBLE
            #pragma multi_compile _ TINT_RED
            float4 vert(float4 position : POSITION) : SV_POSITION {
            #ifdef WOBBLE
                position.x += 0.25;
            #endif
                return position;
            }
            float4 frag() : SV_Target {
            #ifdef TINT_RED
                return float4(1, 0, 0, 1);
            #else
                return float4(1, 1, 1, 1);
            #endif
            }
            ENDCG
        }
    }
}
