// Evaluates built-in include functions (docs/BUILTIN_API.md, issue #27) at every pixel of a
// full-target quad, one group per variant, so that tests/vulkan/BuiltinApiValueTest.cpp can
// compare lavapipe's result with the documented formula computed on the CPU. Pixel centre
// (u, v) in (0, 1)^2 is the input; each variant writes four floats.
Shader "Test/BuiltinApiValues" {
    SubShader {
        Pass {
            Cull Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 3.0
            #pragma multi_compile API_GAMMA API_GAMMA_EXACT API_PARALLAX API_HEIGHTMAP API_NORMAL_SCALE API_NORMAL API_ENCODE_FLOAT API_SRGB API_GAMMA22 API_PQ API_PRIMARIES API_SHADOW_MIX API_TERRAIN_WAVES API_TRANSFORM_TEX API_VIEW_NORMAL API_STRIPE API_DEPTH API_SQUASH_FLIP API_ROTATE_DITHER API_PAINT API_TESSELLATION API_RGBM API_DECODE_MISC API_UI API_NORMAL_FRAME API_PCF
            #if defined(API_SHADOW_MIX)
                // A realtime shadow and a baked shadow mask (no texture is declared for either).
                #define SHADOWS_SCREEN
                #define SHADOWS_SHADOWMASK
            #endif
            #if defined(API_PCF)
                // A collector's own shadow map (the test binds white: depth 1 everywhere).
                #include "HLSLSupport.cginc"
                UNITY_DECLARE_SHADOWMAP(_ShadowMapTexture);
                #define SHADOWMAPSAMPLER_AND_TEXELSIZE_DEFINED
            #endif
            #include "UnityCG.cginc"
            #include "UnityShadowLibrary.cginc"
            #include "UnityColorGamut.cginc"
            #include "TerrainEngine.cginc"
            #include "TerrainPreview.cginc"
            #include "TerrainTool.cginc"
            #include "UnitySprites.cginc"
            #include "UnityCustomRenderTexture.cginc"
            #include "UnityBuiltin3xTreeLibrary.cginc"
            #include "Tessellation.cginc"
            #include "UnityUI.cginc"
            #include "UnityStandardUtils.cginc"

            sampler2D _ApiMain, _ApiAlpha;  // the test binds white textures

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

            static const float4 api_ST = float4(2.0, -3.0, 0.25, 0.5);  // TRANSFORM_TEX(uv, api)

            float4 frag(Interpolators i) : SV_Target {
                float u = i.uv.x, v = i.uv.y;
            #if defined(API_GAMMA)
                return float4(LinearToGammaSpace(float3(u, v, u * v)), IsGammaSpace() ? 1.0 : 0.0);
            #elif defined(API_GAMMA_EXACT)
                return float4(GammaToLinearSpace(float3(u, v, u * v)), LinearToGammaSpaceExact(u) + GammaToLinearSpaceExact(v));
            #elif defined(API_PARALLAX)
                float3 viewDir = float3(u - 0.5, v - 0.5, 0.3 + u);
                return float4(ParallaxOffset(u, 0.2 + 0.5 * v, viewDir), ParallaxOffset(v, 0.4, viewDir.yxz));
            #elif defined(API_HEIGHTMAP)
                return float4(UnpackHeightmap(float4(u, v, 0.3, 0.7)), UnpackHeightmap(PackHeightmap(u)), PackHeightmap(v).rg);
            #elif defined(API_NORMAL_SCALE)
                return float4(UnpackNormalWithScale(float4(u, v, 0.5 + 0.5 * u * v, 1), 0.25 + 2.0 * u * v), 0);
            #elif defined(API_NORMAL)
                return float4(UnpackNormal(float4(u, v, 1 - u * v, 0.5)), 0);
            #elif defined(API_ENCODE_FLOAT)
                float x = u * 0.999;
                return float4(DecodeFloatRGBA(EncodeFloatRGBA(x)), DecodeFloatRG(EncodeFloatRG(x)), EncodeFloatRG(v * 0.973));
            #elif defined(API_SRGB)
                return float4(LinearToSRGB(float3(u, v, u * v * 0.01)), SRGBToLinear(float3(v, 0, 0)).r);
            #elif defined(API_GAMMA22)
                return float4(Gamma22ToLinear(float3(u, v, 0)).rg, LinearToGamma22(float3(u, v, 0)).rg);
            #elif defined(API_PQ)
                return float4(LinearToST2084(float3(u, v * 0.01, u * v)), ST2084ToLinear(float3(v, 0, 0)).r);
            #elif defined(API_PRIMARIES)
                float3 c = float3(u, v, 1 - u);
                float3 wide = mul(Rec709ToRec2020, c);
                float3 p3 = mul(Rec709ToP3D65Mat, c);
                return float4(wide.r, p3.b, mul(Rec2020ToRec709, wide).g, mul(P3D65MatToRec709, p3).b);
            #elif defined(API_SHADOW_MIX)
                return float4(UnityMixRealtimeAndBakedShadows(u, v, 0.5 * u * v), 0, 0, 0);
            #elif defined(API_TRANSFORM_TEX)
                float3 n = normalize(float3(u - 0.5, v - 0.5, 0.6));
                return float4(TRANSFORM_TEX(float2(u, v), api), EncodeViewNormalStereo(n));
            #elif defined(API_VIEW_NORMAL)
                float3 n = normalize(float3(u - 0.5, v - 0.5, 0.6));
                return float4(DecodeViewNormalStereo(float4(EncodeViewNormalStereo(n), 0, 0)), 0);
            #elif defined(API_STRIPE)
                return float4(Stripe(u, 0.5, 0.2), Stripe(v, 0.3, 0.05), 0, 0);
            #elif defined(API_DEPTH)
                return float4(Linear01Depth(u), LinearEyeDepth(v), 0, 0);
            #elif defined(API_SQUASH_FLIP)
                return float4(Squash(float4(u, v, u * v, 1)).xyz, UnityFlipSprite(float3(u, v, 0.3), fixed2(-1, 1)).x);
            #elif defined(API_ROTATE_DITHER)
                float2 pixel = floor(i.uv * 32.0) + 0.5;
                return float4(CustomRenderTextureRotate2D(float2(u, v), v * 3.0), ScreenDitherToAlpha(pixel.x, pixel.y, u), 0);
            #elif defined(API_PAINT)
                return float4(PaintContextUVToBrushUV(float2(u, v)), PaintContextPixelsToBrushUV(float2(u, v) * 32.0));
            #elif defined(API_TESSELLATION)
                float4 tess = UnityCalcTriEdgeTessFactors(float3(u, v, u * v) * 8.0);
                return float4(tess.x, tess.w, UnityDistanceFromPlane(float3(u, v, 1), float4(0.6, 0.8, 0, -0.5)),
                              UnityCalcEdgeTessFactor(float3(u, 0, 2), float3(u + 0.5, v, 2), 4.0));
            #elif defined(API_RGBM)
                half4 rgbm = UnityEncodeRGBM(half3(u * 4.0, v * 2.0, u * v), 5.0);
                return float4(DecodeLightmapRGBM(rgbm, half4(5.0, 1.0, 0, 0)), rgbm.a);
            #elif defined(API_DECODE_MISC)
                float4x4 m = float4x4(2, 0.5, 0, 0.1, -1, 3, 0, 0.2, 0, 0, 1, 0, 0, 0, 0, 1);
                return float4(MultiplyUV(m, float2(u, v)),
                              DecodeHDR(half4(u, v, 0.5, v), half4(3.0, 2.2, 0, 1), 1).r
                                  + DecodeHDR(half4(u, v, 0.5, v), half4(3.0, 2.2, 0, 1), 0).g,
                              UnpackNormalmapRGorAG(half4(1, v, 0.5, u)).z + DecodeLightmapDoubleLDR(half4(u, v, 0, 1), half4(2, 0, 0, 0)).g);
            #elif defined(API_UI)
                half3 linearColor = UIGammaToLinear(half3(u, v, 0));
                return float4(linearColor.rg, UnityGet2DClipping(float2(u, v), float4(0.25, 0.3, 0.75, 0.6)),
                              UnityGetUIDiffuseColor(float2(u, v), _ApiMain, _ApiAlpha, fixed4(0.1, 0.2, 0.3, u)).a);
            #elif defined(API_NORMAL_FRAME)
                half3 dxt = UnpackScaleNormalDXT5nm(half4(0, v, 0, u), 0.8);
                half3x3 frame = CreateTangentToWorldPerVertex(half3(0, 0, 1), half3(u, v, 0), 1);
                half3 bumped = PerturbNormal(half3(0, 0, 1), half3(1, 0, 0), half3(0, 1, 0), u - 0.5, v * 0.3);
                return float4(dxt.x, dxt.z, frame[1].x, bumped.x);
            #elif defined(API_PCF)
                float4 coord = float4(float2(u, v) * 2.0, u * 4.0, 2.0);  // depth 2u after the divide
                float3 bias = UnityGetReceiverPlaneDepthBias(coord.xyz, 1.0);
                return float4(UnitySampleShadowmap_PCF3x3(coord, bias), UnitySampleShadowmap_PCF5x5Tent(coord, bias),
                              UnitySampleShadowmap_PCF7x7(coord, bias),
                              UnityCombineShadowcoordComponents(float2(u, v), float2(0.5, 0.25), v, float3(2, 4, 0)).z);
            #else // API_TERRAIN_WAVES
                float4 x = float4(u, v, 4 * u - 1.3, 3 * v + 0.2);
                return float4(TriangleWave(x).x, SmoothCurve(x * 0.5 + 0.25).y, SmoothTriangleWave(x).z, SmoothTriangleWave(x).w);
            #endif
            }
            ENDCG
        }
    }
}
