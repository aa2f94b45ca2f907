Shader "Case/SurfaceWave" {
    Properties {
        _MainTex ("Albedo", 2D) = "white" {}
        _Amount ("Wave", Range(0, 1)) = 0.1
    }
    SubShader {
        Tags { "RenderType" = "Opaque" }
        CGPROGRAM
        #pragma surface surf Lambert vertex:wave finalcolor:tint
        #pragma multi_compile _ WAVE_ON
        sampler2D _MainTex;
        float _Amount;
        struct Input {
            float2 uv_MainTex;
            float3 viewDir;
            float height;
        };
        void wave(inout appdata_full v, out Input o) {
            UNITY_INITIALIZE_OUTPUT(Input, o);
        #ifdef WAVE_ON
            v.vertex.y += sin(v.vertex.x * 10) * _Amount;
        #endif
            o.height = v.vertex.y;
        }
        void tint(Input IN, SurfaceOutput o, inout fixed4 color) {
            color.rgb *= saturate(IN.height + 0.5);
        }
        void surf(Input IN, inout SurfaceOutput o) {
            o.Albedo = tex2D(_MainTex, IN.uv_MainTex).rgb * saturate(dot(IN.viewDir, float3(0, 1, 0)));
        }
        ENDCG
    }
    Fallback "Legacy Shaders/VertexLit"
}
