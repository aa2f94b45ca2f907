// A small uber shader: two multi_compile sets, instancing, three shader_feature sets.
Shader "Test/Uber" {
    SubShader {
        Pass {
            Name "FORWARD"
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile _ FOG_EXP2
            #pragma multi_compile _ INSTANCING_ON
            #pragma shader_feature _ _DETAIL
            #pragma shader_feature _NORMALMAP
            #pragma shader_feature_local _TINT_RED _TINT_BLUE
            float4 vert(float4 position : POSITION) : SV_POSITION { return position; }
            float4 frag() : SV_Target {
                float4 color = 0;
            #if defined(_TINT_RED)
                color.r = 1;
            #elif defined(_TINT_BLUE)
                color.b = 1;
            #endif
            #ifdef _DETAIL
                color.g = 0.5;
            #endif
            #ifdef _NORMALMAP
                color.a = 0.5;
            #endif
            #ifdef FOG_EXP2
                color *= 0.5;
            #endif
                return color;
            }
            ENDCG
        }
    }
}
