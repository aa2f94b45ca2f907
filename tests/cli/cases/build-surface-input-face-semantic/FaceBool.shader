// SPDX-License-Identifier: Apache-2.0
// A surface Input member with the SV_IsFrontFace semantic, declared bool; with dithercrossfade.
Shader "Test/FaceSurfBool" {
    Properties { _Color ("Color", Color) = (1,1,1,1) }
    SubShader {
        Tags { "RenderType"="Opaque" }
        Cull Off
        CGPROGRAM
        #pragma surface surf Lambert noforwardadd nolightmap nodynlightmap nodirlightmap nofog noshadow dithercrossfade
        fixed4 _Color;
        struct Input { float2 uv_MainTex; bool front : SV_IsFrontFace; };
        void surf (Input IN, inout SurfaceOutput o) {
            o.Albedo = IN.front ? _Color.rgb : 1 - _Color.rgb;
        }
        ENDCG
    }
}
