// For the `build --direct` cases: one pass whose colour comes from an include found through -I.
Shader "Test/DirectTint" {
    SubShader {
        Pass {
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "Tint.cginc"
            float4 vert(float4 position : POSITION) : SV_POSITION { return position; }
            float4 frag() : SV_Target { return TINT; }
            ENDCG
        }
    }
}
