// SPDX-License-Identifier: Apache-2.0
// builtin.longtail-includes: UnityIndirect.cginc as Graphics.RenderPrimitivesIndirect's
// documented usage calls it (per-draw arguments, relative vertex and instance ids), indexed and not.
Shader "Test/Longtail/Indirect" {
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 4.5
            #pragma multi_compile _ INDEXED
            #ifdef INDEXED
            #define UNITY_INDIRECT_DRAW_ARGS IndirectDrawIndexedArgs
            #else
            #define UNITY_INDIRECT_DRAW_ARGS IndirectDrawArgs
            #endif
            #include "UnityCG.cginc"
            #include "UnityIndirect.cginc"
            StructuredBuffer<float3> _Positions;
            struct v2f {
                float4 pos : SV_POSITION;
                float4 color : COLOR0;
            };
            v2f vert(uint svVertexID : SV_VertexID, uint svInstanceID : SV_InstanceID) {
                InitIndirectDrawArgs(0);
                v2f o;
                uint cmdID = GetCommandID(0);
                uint vertexID = GetIndirectVertexID(svVertexID);
                uint instanceID = GetIndirectInstanceID(svInstanceID);
                float3 p = _Positions[GetIndirectVertexID_Base(svVertexID)] + float3(instanceID, cmdID, 0);
                o.pos = mul(UNITY_MATRIX_VP, float4(p, 1));
                o.color = float4((float)vertexID / GetIndirectVertexCount(), (float)instanceID / GetIndirectInstanceCount(),
                                 GetIndirectInstanceID_Base(svInstanceID), 1);
                return o;
            }
            float4 frag(v2f i) : SV_Target {
                return i.color;
            }
            ENDCG
        }
    }
}
