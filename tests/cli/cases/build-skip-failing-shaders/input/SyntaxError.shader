Shader "Test/Skip/SyntaxError" {
    SubShader {
        Pass {
            Blend Sideways
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            float4 vert(float4 position : POSITION) : SV_POSITION { return position; }
            float4 frag() : SV_Target { return 1; }
            ENDCG
        }
    }
}
