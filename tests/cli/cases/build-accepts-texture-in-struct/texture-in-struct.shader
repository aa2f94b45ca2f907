Shader "Test/TextureInStruct" {
    SubShader { Pass {
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        Texture2D _MainTex;
        SamplerState sampler_MainTex;
        struct TextureAndSampler {
            Texture2D tex;
            SamplerState samp;
        };
        float4 sampleIt(TextureAndSampler ts, float2 uv) { return ts.tex.Sample(ts.samp, uv); }
        float4 vert(float4 v : POSITION) : SV_POSITION { return v; }
        float4 frag(float4 pos : SV_POSITION) : SV_Target {
            TextureAndSampler ts;
            ts.tex = _MainTex;
            ts.samp = sampler_MainTex;
            return sampleIt(ts, pos.xy);
        }
        ENDCG
    } }
}
