Shader "Case/Shiny" {
    SubShader {
        CGPROGRAM
        #pragma surface surf Lambert noforwardadd shiny
        struct Input { float2 uv_MainTex; };
        void surf(Input IN, inout SurfaceOutput o) { o.Albedo = 1; }
        ENDCG
    }
}
