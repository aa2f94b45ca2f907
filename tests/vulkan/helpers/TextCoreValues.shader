// SPDX-License-Identifier: Apache-2.0
// Evaluates functions of TextCore_SDF_SSD.cginc at every pixel of a full-target quad (pixel centre (u, v) as
// input, four floats per variant) for tests/vulkan/TextCoreSimpleValueTest.cpp.
Shader "Test/TextCoreValues" {
    SubShader {
        Pass {
            Cull Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile API_SRGB4
            #include "TextCore_SDF_SSD.cginc"
            struct Interpolators { float4 pos : SV_POSITION; float2 uv : TEXCOORD0; };
            Interpolators vert(float4 vertex : POSITION, float2 uv : TEXCOORD0) {
                Interpolators i;
                i.pos = float4(vertex.xy, 0.5, 1.0);
                i.uv = uv;
                return i;
            }
            float4 frag(Interpolators i) : SV_Target {
                float u = i.uv.x, v = i.uv.y;
                return SRGBToLinear(float4(u, v, u * v, 0.25 + v));
            }
            ENDCG
        }
    }
}
