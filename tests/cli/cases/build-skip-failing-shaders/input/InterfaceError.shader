Shader "Test/Skip/InterfaceError" {
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            struct v2f { float4 position : SV_POSITION; };
            struct f2 { float4 position : SV_POSITION; float4 colour : COLOR0; };
            v2f vert(float4 position : POSITION) { v2f o; o.position = position; return o; }
            float4 frag(f2 i) : SV_Target { return i.colour; }
            ENDCG
        }
    }
}
