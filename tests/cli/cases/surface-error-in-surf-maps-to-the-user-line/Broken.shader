Shader "Case/Broken" {
    SubShader {
        CGPROGRAM
        #pragma surface surf Lambert noforwardadd
        struct Input { float2 uv_MainTex; };
        sampler2D _MainTex;
        void surf(Input IN, inout SurfaceOutput o) {
            fixed4 c = tex2D(_MainTex, IN.uv_MainTex);
            o.Albedo = c.rgb * undeclaredScale;
        }
        ENDCG
    }
}
