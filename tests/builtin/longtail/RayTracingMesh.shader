// SPDX-License-Identifier: Apache-2.0
// builtin.longtail-includes: UnityRayTracingMeshUtils.cginc's fetches, compiled in the vertex and
// fragment stages (varc traces no rays; the reads are ordinary storage-buffer loads).
Shader "Test/Longtail/RayTracingMesh" {
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 4.5
            #include "UnityCG.cginc"
            #include "UnityRayTracingMeshUtils.cginc"
            struct v2f {
                float4 pos : SV_POSITION;
                float2 uv : TEXCOORD0;
                nointerpolation uint primitive : TEXCOORD1;
            };
            v2f vert(uint id : SV_VertexID) {
                v2f o;
                uint3 tri = UnityRayTracingFetchTriangleIndices(id / 3);
                uint v = id % 3 == 0 ? tri.x : (id % 3 == 1 ? tri.y : tri.z);
                o.pos = UnityObjectToClipPos(UnityRayTracingFetchVertexAttribute3(v, kVertexAttributePosition));
                o.uv = UnityRayTracingFetchVertexAttribute2(v, kVertexAttributeTexCoord0);
                o.primitive = id / 3;
                return o;
            }
            float4 frag(v2f i) : SV_Target {
                uint3 tri = UnityRayTracingFetchTriangleIndices(i.primitive);
                float4 color = UnityRayTracingHasVertexAttribute(kVertexAttributeColor)
                    ? UnityRayTracingFetchVertexAttribute4(tri.x, kVertexAttributeColor) : float4(1, 1, 1, 1);
                float3 n = UnityRayTracingFetchVertexAttribute3(tri.y, kVertexAttributeNormal);
                return color * saturate(n.z) + float4(i.uv, DecodeSNorm16(tri.z), 0);
            }
            ENDCG
        }
    }
}
