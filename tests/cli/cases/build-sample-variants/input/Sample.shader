Shader "Test/Sample/Twelve" {
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile _ RED GREEN
            #pragma multi_compile _ BRIGHT
            #pragma multi_compile _ DIM HALF
            float4 vert(float4 position : POSITION) : SV_Position { return position; }
            float4 frag() : SV_Target {
                float4 colour = float4(0.5, 0.5, 0.5, 1);
            #if defined(RED)
                colour.r = 1;
            #elif defined(GREEN)
                colour.g = 1;
            #endif
            #ifdef BRIGHT
                colour.rgb *= 2;
            #endif
            #if defined(DIM)
                colour.rgb *= 0.25;
            #elif defined(HALF)
                colour.rgb *= 0.5;
            #endif
                return colour;
            }
            ENDCG
        }
    }
}
