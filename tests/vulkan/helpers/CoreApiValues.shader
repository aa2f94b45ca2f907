// Evaluates the core built-in API added for issue #27 by the "core-api" work (projective and
// shadow sampling of HLSLSupport.cginc, older BRDF terms, stereo UV adjustment, the legacy
// vertex-lit combine, low-discrepancy points and local frames) at every pixel of a full-target quad, one group per variant, so that
// tests/vulkan/CoreApiValueTest.cpp can compare lavapipe's result with the formula on the CPU.
// Pixel centre (u, v) in (0, 1)^2 is the input; each variant writes four floats.
Shader "Test/CoreApiValues" {
    SubShader {
        Pass {
            Cull Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 3.0
            #pragma multi_compile CORE_PROJ CORE_BRDF CORE_BRDF_FRESNEL CORE_STEREO CORE_VERTEX_LIT CORE_HAMMERSLEY CORE_FRAME
            #include "UnityCG.cginc"
            #include "UnityImageBasedLighting.cginc"

            // The test binds the light falloff table (f(t) in every channel, t along u) to
            // _ApiFalloff and white textures to the others.
            sampler2D _ApiFalloff, _ApiWhite;

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
            #if defined(CORE_PROJ)
                float w = 0.5 + v, w2 = 2.0 - u;
                return float4(tex2Dproj(_ApiFalloff, float3(u * w, 0.5 * w, w)).r,
                              tex2Dproj(_ApiFalloff, float4(v * w2, 0.5 * w2, 0.7, w2)).r,
                              tex2DprojShadow(_ApiWhite, float4(0.3 * w, 0.6 * w, 1.5 * u * w, w)).r,
                              tex2DprojShadow(_ApiWhite, float3(0.3, 0.6, 2.0 * v)).r);
            #elif defined(CORE_BRDF)
                return float4(SmithVisibilityTerm(u, v, 0.2 + 0.5 * u),
                              SmithBeckmannVisibilityTerm(u, v, 0.1 + 0.8 * v),
                              NDFBlinnPhongNormalizedTerm(u, 1.0 + 60.0 * v),
                              PerceptualRoughnessToSpecPower(0.05 + 0.9 * u));
            #elif defined(CORE_BRDF_FRESNEL)
                return float4(FresnelLerpFast(half3(0.04, 0.5, u), half3(1.0, v, 0.2), u * v),
                              Pow4(float2(u, v)).y + Pow5(half3(u, v, 0.5)).x + Pow4(half4(0, 0, v, 0)).z
                              + Pow5(half2(0, u)).y + Pow4(half3(0, 0, u)).z + Pow5(half4(v, 0, 0, 0)).x);
            #elif defined(CORE_STEREO)
                return float4(UnityStereoScreenSpaceUVAdjustInternal(float2(u, v), float4(0.5, 2.0, 0.25, -1.0)),
                              UnityStereoScreenSpaceUVAdjustInternal(float4(u, v, v, u), float4(3.0, -1.0, 0.5, 0.125)).zw);
            #elif defined(CORE_HAMMERSLEY)
                // Point i = 32 x + y of n = 1024 (x, y the pixel), and the bit reversal of i.
                uint index = uint(u * 32.0) * 32u + uint(v * 32.0);
                float2 h = Hammersley2d(index, 1024u);
                return float4(h, RadicalInverse_VdC(index << 7), float(ReverseBits32(index) >> 22));
            #elif defined(CORE_FRAME)
                // A frame around N = normalize(u - 0.5, v - 0.5, 0.8 - u) (|N.z| < 0.999): the
                // tangent's x and y, the bitangent's z and the largest dot product of the three.
                float3 n = normalize(float3(u - 0.5, v - 0.5, 0.8 - u));
                float3 tx, ty;
                GetLocalFrame(n, tx, ty);
                return float4(tx.xy, ty.z, max(abs(dot(tx, ty)), max(abs(dot(tx, n)), abs(dot(ty, n)))));
            #else // CORE_VERTEX_LIT
                v2f_vertex_lit l;
                l.uv = float2(u, 0.5);
                l.diff = half4(u, v, 0.5, v);
                l.spec = half4(v, 0.2, u, 0.9);
                return VertexLight(l, _ApiFalloff);
            #endif
            }
            ENDCG
        }
    }
}
