// SPDX-License-Identifier: Apache-2.0
// A surface Input member with the VFACE semantic: +1 on front faces, -1 on back faces.
Shader "Test/FaceSurf" {
    Properties { _Color ("Color", Color) = (1,1,1,1) }
    SubShader {
        Tags { "RenderType"="Opaque" }
        Cull Off
        CGPROGRAM
        #pragma surface surf Lambert noforwardadd nolightmap nodynlightmap nodirlightmap nofog noshadow
        fixed4 _Color;
        struct Input { float2 uv_MainTex; fixed facing : VFACE; };
        void surf (Input IN, inout SurfaceOutput o) {
            o.Albedo = IN.facing > 0 ? _Color.rgb : _Color.rgb * 0.5;
        }
        ENDCG
    }
}
