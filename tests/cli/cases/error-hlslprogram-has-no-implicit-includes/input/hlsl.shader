Shader "Test/HlslNoImplicitIncludes" {
    SubShader {
        Pass {
            HLSLPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            float4 vert(float4 p : POSITION) : SV_POSITION { return p; }
            float4 frag() : SV_Target { return _Time; }
            ENDHLSL
        }
    }
}
