// SPDX-License-Identifier: Apache-2.0
// Evaluates functions of the virtual-texturing, UI Toolkit, indirect-draw and ray-tracing include
// files (issue #27) at every pixel of a full-target quad, one group per variant, for
// tests/vulkan/LongtailApiValueTest.cpp to compare with the formulas computed on the CPU. Pixel
// centre (u, v) in (0, 1)^2 is the input; each variant writes four floats.
Shader "Test/LongtailApiValues" {
    SubShader {
        Pass {
            Cull Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 4.5
            #pragma multi_compile LT_GRANITE_UV LT_GRANITE_MIP LT_GRANITE_CUBE LT_GRANITE_TILE LT_GRANITE_NORMAL LT_UIE_COLOR LT_UIE_GEOMETRY LT_UIE_FLAGS LT_INDIRECT_RT
            #define UIE_CUSTOM_SHADER
            #include "UnityCG.cginc"
            #include "GraniteShaderLib3.cginc"
            #include "UnityUIE.cginc"
            #include "UnityIndirect.cginc"
            #include "UnityRayTracingMeshUtils.cginc"

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

            // A streaming texture of 256 x 128 texels, transform scale (0.5, 2), offset (0.25, -1).
            GraniteStreamingTextureConstantBuffer streamingTexture() {
                GraniteStreamingTextureConstantBuffer st;
                st.data[0] = float4(0.5, 2.0, 0.25, -1.0);
                st.data[1] = float4(256.0, 128.0, 7.0, 0.0);
                return st;
            }
            // A tile set with a maximum anisotropy of 2^2 and an LOD bias of 2.
            GraniteTilesetConstantBuffer tileset() {
                GraniteTilesetConstantBuffer ts = (GraniteTilesetConstantBuffer)0;
                ts.data[0][0][3] = 2.0;
                ts.data[0][1][2] = 2.0;
                return ts;
            }

            float4 frag(Interpolators i) : SV_Target {
                float u = i.uv.x, v = i.uv.y;
                GraniteStreamingTextureConstantBuffer st = streamingTexture();
            #if defined(LT_GRANITE_UV)
                float2 x = float2(4.0 * u - 2.0, 3.0 * v - 1.0);
                return float4(GranitePrivate_RepeatUV(x, st).x, GranitePrivate_MirrorUV(x, st).y,
                              GranitePrivate_ClampUV(x, st).x, Granite_Transform(st, x).y);
            #elif defined(LT_GRANITE_MIP)
                float2 dx = float2(0.01 * u, 0.0), dy = float2(0.0, 0.004 * v + 0.0005);
                GraniteTilesetConstantBuffer tsCB = Granite_ApplyResolutionOffset(tileset(), 0.5 + u);
                return float4(GranitePrivate_CalcMiplevelLinear(tsCB, st, dx, dy),
                              GranitePrivate_CalcMiplevelAnisotropic(tsCB, st, dx, dy),
                              GranitePrivate_Pow2((uint)(8.0 * u)) / 256.0, gra_LodBiasPow2);
            #elif defined(LT_GRANITE_CUBE)
                GraniteStreamingTextureCubeConstantBuffer faces = (GraniteStreamingTextureCubeConstantBuffer)0;
                int face;
                float2 coord, dX, dY;
                GranitePrivate_CalculateCubemapCoordinates(float3(4.0 * u - 2.0, 4.0 * v - 1.9, 1.05),
                    float3(0.1, 0.05, 0.02), float3(0, 0, 0), faces, face, coord, dX, dY);
                return float4(face / 5.0, coord, dX.x + dX.y);
            #elif defined(LT_GRANITE_TILE)
                float2 tile = floor(float2(200.0 * u, 100.0 * v));
                float4 packed = GranitePrivate_PackTileId(tile, floor(10.0 * u), 7.0);
                float4 unpacked = GranitePrivate_UnpackTileId(packed);
                float4 merged = Granite_MergeResolveOutputs(float4(u, u, u, u), float4(v, v, v, v), i.uv * 32.0);
                return float4(unpacked.x / 255.0 + unpacked.w / 1000.0, Granite_PackTileId(unpacked).y,
                              Granite_DebugPackedTileId64(packed).x, merged.x);
            #elif defined(LT_GRANITE_NORMAL)
                float3 n = Granite_UnpackNormal(float4(u, v, 0, 0), 0.5 + u);
                return float4(n, Granite_UnpackNormal(float4(v, u, 0, 0)).z);
            #elif defined(LT_UIE_COLOR)
                fixed4 bytes = fixed4(u, v, 1.0 - u, 0.5);
                float2 words = uie_unpack_float2(bytes);
                return float4(uie_gamma_to_linear(half3(u, 0, 0)).x, uie_linear_to_gamma(half3(v, 0, 0)).x,
                              words.x / 65535.0, words.y / 65535.0);
            #elif defined(LT_UIE_GEOMETRY)
                float angle = 6.2831853 * u;
                float2 hit = uie_ray_unit_circle_first_hit(float2(u - 0.5, v - 0.5) * 0.8, float2(cos(angle), sin(angle)));
                float radial = uie_radial_address(float2(2.0 * u - 1.0, 2.0 * v - 1.0) * 0.7, float2(0.2, -0.1));
                return float4(hit, radial, ComputeRelativeClipRectCoords(float2(0.1, 0.2), float2(0.9, 0.6), float2(u, v)).y);
            #elif defined(LT_UIE_FLAGS)
                float flags = floor(16.0 * u);
                float bit8 = TestForValue(8.0, flags), bit4 = TestForValue(4.0, flags);
                float2 texel = uie_decode_shader_info_texel_pos(floor(float2(3.0 * u, 2.0 * v)), floor(100.0 * v), 3.0);
                float2 border = uie_get_border_offset(float4(0, 0, 0, 1), float2(u - 0.5, v - 0.5) * 0.2, 0.05, false, v > 0.5);
                return float4(bit8 + 2.0 * bit4 + flags / 16.0, texel.x / 100.0, texel.y / 1000.0, border.x + border.y);
            #else // LT_INDIRECT_RT
                IndirectDrawArgs args;
                args.vertexCountPerInstance = 30;
                args.instanceCount = 5;
                args.startVertex = 7;
                args.startInstance = 3;
                IndirectDrawIndexedArgs indexed = (IndirectDrawIndexedArgs)0;
                indexed.baseVertexIndex = 11;
                indexed.startInstance = 2;
                uint k = (uint)(100.0 * u), n = (uint)(10.0 * v);
                return float4(DecodeSNorm16((uint)(65535.0 * u)),
                              (float)GetIndirectVertexID(args, k + 7) / 100.0 + (float)GetIndirectInstanceID(args, n + 3) / 10.0,
                              (float)GetIndirectVertexID(indexed, k + 11) / 100.0 + (float)GetIndirectInstanceID_Base(indexed, n) / 10.0,
                              (float)GetCommandID((uint)(4.0 * v)) / 4.0 + (float)GetIndirectVertexID_Base(args, k) / 1000.0);
            #endif
            }
            ENDCG
        }
    }
}
