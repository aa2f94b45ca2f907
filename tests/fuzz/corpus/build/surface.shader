Shader "FuzzBuild/Surface" {
    Properties { _MainTex ("Albedo", 2D) = "white" {} _Glossiness ("Smoothness", Range(0,1)) = 0.5 }
    SubShader {
        Tags { "RenderType"="Opaque" }
        CGPROGRAM
        #pragma surface surf Lambert noforwardadd nolightmap nodynlightmap nodirlightmap nofog nometa noshadow
        #pragma skip_variants VERTEXLIGHT_ON SHADOWS_SHADOWMASK LIGHTMAP_SHADOW_MIXING
        sampler2D _MainTex;
        struct Input { float2 uv_MainTex; };
        void surf(Input IN, inout SurfaceOutput o) { o.Albedo = tex2D(_MainTex, IN.uv_MainTex).rgb; }
        ENDCG
    }
}
