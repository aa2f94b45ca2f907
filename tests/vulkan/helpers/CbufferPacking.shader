// SPDX-License-Identifier: Apache-2.0
// A cbuffer in HLSL's packing, as Unity-era shaders declare their materials: _B (float3) right
// after _A (float) at offset 4, then _C in the same 16 bytes as _B (RelaxedBlockLayoutTest).
Shader "varc-test/CbufferPacking" {
    Properties {
        _A ("A", Float) = 0
        _B ("B", Vector) = (0, 0, 0, 0)
        _C ("C", Float) = 0
    }
    SubShader {
        Pass {
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            CBUFFER_START(UnityPerMaterial)
                float _A;
                float3 _B;
                float _C;
            CBUFFER_END
            float4 vert(float4 vertex : POSITION) : SV_POSITION { return UnityObjectToClipPos(vertex); }
            float4 frag() : SV_Target { return float4(_B, _A + _C); }
            ENDCG
        }
    }
}
