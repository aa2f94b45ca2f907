Shader "Case/Tint" {
    SubShader {
        CGPROGRAM
        #pragma surface surf Lambert finalcolor:tint noforwardadd
        struct Input { float2 uv_MainTex; };
        // Not the finalcolor shape (Input, SurfaceOutput, inout fixed4): the generated call fails.
        void tint(Input IN, inout fixed4 color) { color.rgb *= 0.5; }
        void surf(Input IN, inout SurfaceOutput o) { o.Albedo = 1; }
        ENDCG
    }
}
