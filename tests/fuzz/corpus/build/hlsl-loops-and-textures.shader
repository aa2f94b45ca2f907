Shader "FuzzBuild/Hlsl" {
    SubShader { Pass {
        Cull Off ZWrite Off Blend SrcAlpha OneMinusSrcAlpha
        HLSLPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #pragma multi_compile _ BLUR_WIDE
        Texture2D _MainTex;
        SamplerState sampler_MainTex;
        float4 _MainTex_TexelSize;
        cbuffer Params { float _Strength; int _Taps; };
        struct appdata { float4 vertex : POSITION; float2 uv : TEXCOORD0; };
        struct v2f { float4 pos : SV_POSITION; float2 uv : TEXCOORD0; };
        v2f vert(appdata v) { v2f o; o.pos = v.vertex; o.uv = v.uv; return o; }
        float4 frag(v2f i) : SV_Target {
            float4 sum = 0;
        #ifdef BLUR_WIDE
            const int taps = 8;
        #else
            const int taps = 3;
        #endif
            [unroll] for (int k = -taps; k <= taps; k++)
                sum += _MainTex.Sample(sampler_MainTex, i.uv + k * _MainTex_TexelSize.xy);
            if (any(sum.rgb > 1)) sum = saturate(sum);
            return lerp(_MainTex.Sample(sampler_MainTex, i.uv), sum / (2 * taps + 1), _Strength);
        }
        ENDHLSL
    } }
}
