// One pass with one variant: a single unit of work, which `--shard 1/2` takes.
Shader "Test/OneVariant" {
    SubShader {
        Pass {
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            float4 vert(float4 position : POSITION) : SV_POSITION { return position; }
            float4 frag() : SV_Target { return float4(1, 0, 0, 1); }
            ENDCG
        }
    }
}
