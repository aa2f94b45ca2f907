// SPDX-License-Identifier: Apache-2.0
// A surface shader with the Lambert lighting model, written for varc's tests: its generated
// ForwardBase and ForwardAdd passes must hold every property relation (docs/PROPERTIES.md).
Shader "varc-tests/SurfaceLambert" {
    Properties {
        _Color ("Colour", Color) = (1, 1, 1, 1)
        _MainTex ("Albedo (RGB)", 2D) = "white" {}
    }
    SubShader {
        Tags { "RenderType" = "Opaque" }
        CGPROGRAM
        #pragma surface surf Lambert
        sampler2D _MainTex;
        fixed4 _Color;

        struct Input {
            float2 uv_MainTex;
        };

        void surf(Input IN, inout SurfaceOutput o) {
            fixed4 c = tex2D(_MainTex, IN.uv_MainTex) * _Color;
            o.Albedo = c.rgb;
            o.Alpha = c.a;
        }
        ENDCG
    }
    Fallback "Legacy Shaders/VertexLit"
}
