// SPDX-License-Identifier: Apache-2.0
// Evaluates HLSLSupport.cginc's texture declaration, sampling, argument-passing and uniform-block
// macros (issue #27) at every pixel of a full-target quad, one group per variant, so that
// tests/vulkan/HlslTextureMacroTest.cpp can compare lavapipe's result with the texels it uploaded.
// Pixel centre (u, v) in (0, 1)^2 is the input; each variant writes four floats. The test binds
// its own 8 x 8 mipmapped 2D texture to every 2D name, a 4 x 4 x 4 volume to every 3D name and a
// cube of six solid faces to every cube name, all sampled nearest (the separate sampler_* states
// too), so every result is one known texel.
Shader "Test/HlslTextureMacros" {
    SubShader {
        Pass {
            Cull Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 3.5
            #pragma multi_compile TM_2D TM_2D_LOD TM_DEPTH TM_SCREEN TM_3D TM_CUBE TM_CUBE_ARGS TM_CUBE_SHADOW TM_BLOCKS TM_STACK TM_STACK_VT TM_GRANITE
            #include "UnityCG.cginc"

            struct Interpolators {
                UNITY_POSITION(pos);
                float2 uv : TEXCOORD0;
            };

            Interpolators vert(float4 vertex : POSITION, float2 uv : TEXCOORD0) {
                Interpolators i;
                i.pos = float4(vertex.xy, 0.5, 1.0);
                i.uv = uv;
                return i;
            }

        #if defined(TM_2D) || defined(TM_2D_LOD)
            UNITY_DECLARE_TEX2D(_TmA);
            UNITY_DECLARE_TEX2D_NOSAMPLER(_TmB);
            UNITY_DECLARE_TEX2D_HALF(_TmHalf);
            UNITY_DECLARE_TEX2D_FLOAT(_TmFloat);
            UNITY_DECLARE_TEX2D_NOSAMPLER_HALF(_TmHalfNs);
            UNITY_DECLARE_TEX2D_NOSAMPLER_FLOAT(_TmFloatNs);
        #elif defined(TM_DEPTH)
            UNITY_DECLARE_DEPTH_TEXTURE(_TmDepth);
            UNITY_DECLARE_SHADOWMAP(_TmShadow);
        #elif defined(TM_SCREEN)
            UNITY_DECLARE_SCREENSPACE_TEXTURE(_TmScreen);
            UNITY_DECLARE_SCREENSPACE_SHADOWMAP(_TmScreenShadow);
            struct TmRecord { float4 a; float2 b; float c; };
        #elif defined(TM_3D)
            UNITY_DECLARE_TEX3D(_TmVol);
            UNITY_DECLARE_TEX3D_HALF(_TmVolHalf);
            UNITY_DECLARE_TEX3D_FLOAT(_TmVolFloat);
            UNITY_DECLARE_TEX3D_NOSAMPLER(_TmVolNs);
        #elif defined(TM_CUBE) || defined(TM_CUBE_ARGS)
            UNITY_DECLARE_TEXCUBE(_TmCube);
            UNITY_DECLARE_TEXCUBE_NOSAMPLER(_TmCubeNs);
            // Cube sampling through function arguments in each of Unity's spellings.
            float4 TmSampleArgs(UNITY_ARGS_TEXCUBE(tex), float3 dir) {
                return UNITY_SAMPLE_TEXCUBE(tex, dir);
            }
            float4 TmSampleNoSampler(UNITY_ARGS_TEXCUBE_NOSAMPLER(tex), SamplerState s, float3 dir) {
                return tex.Sample(s, dir);
            }
            float4 TmSampleLod(UNITY_ARGS_TEXCUBE(tex), float lod, float3 dir) {
                return UNITY_SAMPLE_TEXCUBE_LOD(tex, dir, lod);
            }
        #elif defined(TM_CUBE_SHADOW)
            UNITY_DECLARE_TEXCUBE_SHADOWMAP(_TmCubeShadow);
            samplerCUBE _TmCubeComb;
        #elif defined(TM_STACK) || defined(TM_STACK_VT)
            // UnityLegacyTextureStack.cginc without and with virtual texturing (varc's fallback
            // samples the layer textures directly in both).
            #if defined(TM_STACK_VT)
                #define UNITY_VIRTUAL_TEXTURING 1
            #endif
            #include "UnityLegacyTextureStack.cginc"
            sampler2D _TmStackA, _TmStackN;
            DECLARE_STACK2(_TmStack, _TmStackA, _TmStackN)
        #elif defined(TM_GRANITE)
            // Granite's tile-set accessors and setter, page translation and debug tiles.
            #include "GraniteShaderLib3.cginc"
        #else // TM_BLOCKS
            CBUFFER_START(TmBlockA)
                float4 _TmA4;
            CBUFFER_END
            GLOBAL_CBUFFER_START(TmBlockB)
                float4 _TmB4;
            GLOBAL_CBUFFER_END
            CBUFFER_START_WITH_BINDING(TmBlockC, 0, 5)
                float4 _TmC4;
            CBUFFER_END
            UNITY_INSTANCING_CBUFFER_SCOPE_BEGIN(TmBlockD)
                float4 _TmD4;
            UNITY_INSTANCING_CBUFFER_SCOPE_END
            DECL_WITH_BINDING(float4, _TmE4, 0, 7);
        #endif

            // The direction into the middle part of cube face k = floor(6 u) (Vulkan's order +X,
            // -X, +Y, -Y, +Z, -Z), the in-face offsets (0.8 (frac(6 u) - 0.5), 0.8 (v - 0.5)).
            float3 TmFaceDirection(float u, float v) {
                float k = floor(u * 6.0);
                float a = 0.8 * (frac(u * 6.0) - 0.5), b = 0.8 * (v - 0.5);
                float s = fmod(k, 2.0) < 0.5 ? 1.0 : -1.0;
                float axis = floor(k * 0.5);
                return axis < 0.5 ? float3(s, a, b) : (axis < 1.5 ? float3(a, s, b) : float3(a, b, s));
            }

            float4 frag(Interpolators i) : SV_Target {
                float u = i.uv.x, v = i.uv.y;
                float2 uv = i.uv;
            #if defined(TM_2D)
                return float4(UNITY_SAMPLE_TEX2D(_TmA, uv).r,
                              UNITY_SAMPLE_TEX2D_SAMPLER(_TmB, _TmA, uv.yx).g,
                              UNITY_SAMPLE_TEX2D(_TmHalf, uv).b + UNITY_SAMPLE_TEX2D_SAMPLER(_TmHalfNs, _TmA, uv.yx).r,
                              UNITY_SAMPLE_TEX2D_SAMPLER(_TmFloatNs, _TmFloat, uv).a + UNITY_SAMPLE_TEX2D(_TmFloat, uv.yx).g);
            #elif defined(TM_2D_LOD)
                return float4(UNITY_SAMPLE_TEX2D_LOD(_TmA, uv, 1.0).r,
                              UNITY_SAMPLE_TEX2D_SAMPLER_LOD(_TmB, _TmA, uv, 2.0).g,
                              UNITY_SAMPLE_TEX2D_LOD(_TmHalf, uv.yx, 0.0).r,
                              UNITY_SAMPLE_TEX2D_SAMPLER_LOD(_TmFloatNs, _TmFloat, uv, 3.0).a);
            #elif defined(TM_DEPTH)
                // Depth in .r; shadow compares (u, v, 0.51) with .r: 1 where 0.51 <= r.
                return float4(tex2D(_TmDepth, uv).r,
                              UNITY_SAMPLE_DEPTH(tex2D(_TmDepth, uv.yx)),
                              UNITY_SAMPLE_SHADOW(_TmShadow, float3(uv, 0.51)),
                              UNITY_SAMPLE_SHADOW_PROJ(_TmShadow, float4(uv.yx * 2.0, 0.3 * 2.0, 2.0)));
            #elif defined(TM_SCREEN)
                // The record is zeroed and then one member set; the position is the pixel centre.
                TmRecord r;
                UNITY_INITIALIZE_OUTPUT(TmRecord, r);
                r.b.x = 1.0;
                return float4(UNITY_SAMPLE_SCREENSPACE_TEXTURE(_TmScreen, uv).g,
                              UNITY_SAMPLE_SCREEN_SHADOW(_TmScreenShadow, float4(uv * 4.0, 0.0, 4.0)),
                              dot(r.a, 1.0) + r.b.x + r.b.y + r.c,
                              i.pos.x / 32.0 + i.pos.y);
            #elif defined(TM_3D)
                float3 c = float3(u, v, 0.5 * u + 0.2);
                return float4(UNITY_SAMPLE_TEX3D(_TmVol, c).r,
                              UNITY_SAMPLE_TEX3D_LOD(_TmVolHalf, c.yxz, 0.0).g,
                              UNITY_SAMPLE_TEX3D_SAMPLER(_TmVolNs, _TmVol, c).b,
                              UNITY_SAMPLE_TEX3D_SAMPLER_LOD(_TmVolFloat, _TmVol, c.zyx, 0.0).a);
            #elif defined(TM_CUBE)
                float3 d = TmFaceDirection(u, v);
                return float4(UNITY_SAMPLE_TEXCUBE(_TmCube, d).r,
                              UNITY_SAMPLE_TEXCUBE_LOD(_TmCube, d * 3.0, 0.0).g,
                              UNITY_SAMPLE_TEXCUBE_SAMPLER(_TmCubeNs, _TmCube, d).b,
                              SampleCubeReflection(_TmCube, d, 0.0).a);
            #elif defined(TM_CUBE_ARGS)
                float3 d = TmFaceDirection(u, v);
                return float4(UNITY_SAMPLE_TEXCUBE_SAMPLER_LOD(_TmCubeNs, _TmCube, d, 0.0).r,
                              TmSampleArgs(UNITY_PASS_TEXCUBE(_TmCube), d).g,
                              TmSampleNoSampler(_TmCubeNs, sampler_TmCube, d).b
                                  + TmSampleArgs(UNITY_PASS_TEXCUBE_SAMPLER(_TmCubeNs, _TmCube), d).r,
                              TmSampleLod(UNITY_PASS_TEXCUBE_SAMPLER_LOD(_TmCubeNs, _TmCube, 0.0), d).a);
            #elif defined(TM_CUBE_SHADOW)
                // Cube shadow: 1 where the receiver depth v <= the face's .r.
                float3 d = TmFaceDirection(u, v);
                return float4(UNITY_SAMPLE_TEXCUBE_SHADOW(_TmCubeShadow, float4(d, v)),
                              texCUBEproj(_TmCubeComb, float4(d * 2.5, 2.5)).g,
                              texCUBEproj(_TmCubeComb, float4(-d * 0.5, 0.5)).b,
                              0.0);
            #elif defined(TM_STACK) || defined(TM_STACK_VT)
                StackInfo info = PrepareStack(uv, _TmStack);
                StackInfo lodInfo = PrepareStackLod(uv.yx, _TmStack, 1.0);
                float3 n = SampleStackNormal(info, _TmStackN, 0.5);
                float3 m = SampleStackLodNormal(lodInfo, _TmStackN, 2.0);
                return float4(SampleStack(info, _TmStackA).r + dot(GetResolveOutput(info), 1.0),
                              SampleStackLod(lodInfo, _TmStackA).g, n.z, m.y);
            #elif defined(TM_GRANITE)
                // Tile set: level 0 is 4 tiles wide, y scale 0.5; cache layer 2 holds (u, v, 2u, 3v).
                GraniteTilesetConstantBuffer tsCB = (GraniteTilesetConstantBuffer)0;
                tsCB.data[0][2] = float4(0.0, 0.0, 4.0, 0.5);
                tsCB.data[1][2] = float4(u, v, 2.0 * u, 3.0 * v);
                GraniteTilesetConstantBuffer set = Granite_SetMaxAnisotropy(tsCB, 1.0 + 3.0 * u);
                float2 pages;
                float3 coord = GranitePrivate_TranslateCoord(tsCB, uv, float4(0.5, 2.0, 0.25, -1.0), 3, pages);
                float4 debug = GranitePrivate_DrawDebugTiles(float4(0.0, 0.0, 0.5, 0.0), uv, float2(6.1, 3.0));
                return float4(dot(gra_RcpCacheInTiles(2), float2(1.0, 10.0)) + dot(gra_BorderPixelsRcpCache(2), float2(100.0, 1000.0)),
                              set.data[0][0][3] + 10.0 * tsCB.data[0][0][3],
                              dot(coord, float3(1.0, 10.0, 100.0)) + 1000.0 * (pages.x + 10.0 * pages.y),
                              debug.r + debug.b * 10.0);
            #else // TM_BLOCKS
                return float4(_TmA4.x * u + _TmA4.y, _TmB4.z * v + _TmC4.w,
                              _TmD4.x + _TmD4.w * u, _TmE4.y - _TmE4.z * v);
            #endif
            }
            ENDCG
        }
    }
}
