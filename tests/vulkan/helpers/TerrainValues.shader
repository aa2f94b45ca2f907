// SPDX-License-Identifier: Apache-2.0
// Evaluates TerrainEngine.cginc's vegetation helpers and TerrainPreview.cginc's paint-context
// maps (issue #27) at every pixel of a full-target quad, one group per variant, so that
// tests/vulkan/TerrainValueTest.cpp can compare lavapipe's result with the formula on the CPU.
// Pixel centre (u, v) in (0, 1)^2 is the input; each variant writes four floats; the engine's and
// the tool's uniforms are set by the test.
Shader "Test/TerrainValues" {
    SubShader {
        Pass {
            Cull Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 3.5
            #pragma multi_compile TE_SINCOS TE_GRASS TE_TREE TE_BEND TE_EXPAND TE_WIND TE_MESH TE_OBJECT TE_WORLD TE_SPLAT
            #include "TerrainEngine.cginc"
            #include "TerrainPreview.cginc"
            #if defined(TE_SPLAT)
                #include "Lighting.cginc"
                #include "TerrainSplatmapCommon.cginc"
            #endif

            struct Interpolators {
                float4 pos : SV_POSITION;
                float2 uv : TEXCOORD0;
            };

            Interpolators vert(float4 vertex : POSITION, float2 uv : TEXCOORD0) {
                Interpolators i;
                i.pos = float4(vertex.xy, 0.5, 1.0);
                i.uv = uv;
                return i;
            }

            float4 frag(Interpolators i) : SV_Target {
                float u = i.uv.x, v = i.uv.y;
            #if defined(TE_SINCOS)
                float4 s, c;
                FastSinCos(float4(6.0 * u - 3.0, 10.0 * v, 0.0, -20.0 * u), s, c);
                return float4(s.x, c.y, s.z + c.z, s.w * c.w);
            #elif defined(TE_GRASS)
                float4 p = float4(10.0 * u, 1.0, 10.0 * v, 1.0);
                TerrainBillboardGrass(p, float2(u, v - 0.5));
                return p;
            #elif defined(TE_TREE)
                float4 p = float4(u, v, 2.0, 0.25);
                TerrainBillboardTree(p, float2(u - 0.5, v), 0.5 + u);
                return p;
            #elif defined(TE_BEND)
                float4 p = float4(u, 2.0 * v, 1.0 - u, 1.0);
                TerrainAnimateTree(p, v);
                return float4(p.xyz, p.w);
            #elif defined(TE_EXPAND)
                // Vertices with u < 0.5 are billboard leaves (tangent.w = 0), the others not.
                float4 p = float4(u, v, 0.5, 1.0);
                float3 n = float3(u - 0.5, v, 0.25);
                float4 t = float4(0.0, 1.0, v, u < 0.5 ? 0.0 : -1.0);
                float4x4 m = float4x4(0, 2, 0, 0,  -1, 0, 0, 0,  0, 0, 1, 0,  0, 0, 0, 1);
                ExpandBillboard(m, p, n, t);
                return float4(p.x, p.y + p.z, n.x, t.y);
            #elif defined(TE_WIND)
                // Main bending only (no branch phase, edge flutter or branch bend).
                float4 p = float4(2.0 * u - 1.0, 10.0 * v, 0.5, 1.0);
                float4 q = AnimateVertex(p, float3(0, 1, 0), float4(0.0, 0.0, 2.0 + 4.0 * u, 0.0));
                return float4(q.xyz, length(q.xyz) - length(p.xyz));
            #elif defined(TE_MESH)
                uint id = uint(u * 32.0) * 32u + uint(v * 32.0);
                return float4(BuildProceduralQuadMeshVertex(id), PaintContextPixelsToHeightmapUV(float2(u, v) * 64.0));
            #elif defined(TE_OBJECT)
                return float4(PaintContextPixelsToObjectPosition(float2(u, v) * 64.0, 0.5 * v), 0.0);
            #elif defined(TE_SPLAT)
                // Control texel (f, f, f, f) (the falloff table along u) over four solid layers;
                // the final hooks weight colours by o.Alpha = 0.25 + 0.5 v.
                Input IN;
                UNITY_INITIALIZE_OUTPUT(Input, IN);
                IN.tc = float4(u, v, u, 0.5);
                half4 control;
                half weight;
                fixed4 diffuse;
                fixed3 normal = fixed3(0, 0, 1);
                SplatmapMix(IN, control, weight, diffuse, normal);
                SurfaceOutput o = (SurfaceOutput)0;
                o.Alpha = 0.25 + 0.5 * v;
                fixed4 color = fixed4(1.0, 0.5, 0.25, 1.0);
                SplatmapFinalColor(IN, o, color);
                fixed4 normalSpec = fixed4(0.5, 0.5, 0.5, 0.5);
                SplatmapFinalPrepass(IN, o, normalSpec);
                half4 g0 = 1, g1 = 2, g2 = 4, e = 8;
                SplatmapFinalGBuffer(IN, o, g0, g1, g2, e);
                return float4(diffuse.r + 10.0 * weight, diffuse.g + 10.0 * control.x, color.g + normalSpec.a,
                              g0.x + g1.y + g2.z + e.w);
            #else // TE_WORLD
                return float4(TerrainObjectToWorldPosition(float3(u, v, u * v)), 0.0);
            #endif
            }
            ENDCG
        }
    }
}
