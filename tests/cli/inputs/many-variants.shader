// 512 variants (4 x 4 x 4 x 4 x 2), more than one shard unit: every keyword is named in the text,
// so each variant is preprocessed on its own, but only TINT_* and FOG reach the fragment program
// and only BEND_* the vertex program: 8 fragment and 4 vertex programs.
Shader "Test/ManyVariants" {
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile _ TINT_RED TINT_GREEN TINT_BLUE
            #pragma multi_compile _ BEND_A BEND_B BEND_C
            #pragma multi_compile _ UNUSED_A UNUSED_B UNUSED_C
            #pragma multi_compile _ SPARE_A SPARE_B SPARE_C
            #pragma multi_compile _ FOG
            float4 unused() {
            #if defined(UNUSED_A) || defined(SPARE_A)
                return float4(1, 1, 1, 1);
            #elif defined(UNUSED_B) || defined(SPARE_B)
                return float4(2, 2, 2, 2);
            #elif defined(UNUSED_C) || defined(SPARE_C)
                return float4(3, 3, 3, 3);
            #else
                return float4(0, 0, 0, 0);
            #endif
            }
            float4 vert(float4 position : POSITION) : SV_POSITION {
            #if defined(BEND_A)
                position.x += 0.25;
            #elif defined(BEND_B)
                position.y += 0.25;
            #elif defined(BEND_C)
                position.z += 0.25;
            #endif
                return position;
            }
            float4 frag() : SV_Target {
                float4 color = float4(1, 1, 1, 1);
            #if defined(TINT_RED)
                color = float4(1, 0, 0, 1);
            #elif defined(TINT_GREEN)
                color = float4(0, 1, 0, 1);
            #elif defined(TINT_BLUE)
                color = float4(0, 0, 1, 1);
            #endif
            #ifdef FOG
                color.rgb *= 0.5;
            #endif
                return color;
            }
            ENDCG
        }
    }
}
