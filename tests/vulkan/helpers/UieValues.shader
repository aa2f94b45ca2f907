// SPDX-License-Identifier: Apache-2.0
// Evaluates UnityUIE.cginc's fragment helpers (issue #27: float comparison, pixel footprint,
// signed-distance and rounded-corner coverage, pixel snapping, the texture slots and the shader-
// info texture) at every pixel of a full-target quad, one group per variant, so that
// tests/vulkan/UieValueTest.cpp can compare lavapipe's result with the formula on the CPU. Pixel
// centre (u, v) in (0, 1)^2 is the input (uv changes by 1/32 per pixel, so fwidth(k uv) = k/32 on
// each axis); each variant writes four floats.
Shader "Test/UieValues" {
    SubShader {
        Pass {
            Cull Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 3.5
            #pragma multi_compile UE_BASICS UE_TEXT UE_SLOTS
            #define UIE_CUSTOM_SHADER
            #include "UnityCG.cginc"
            #include "UnityUIE.cginc"

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
                float2 uv = i.uv;
            #if defined(UE_BASICS)
                float equal = (fpEqual(u, v) ? 1.0 : 0.0) + (fpEqual(u, u + 5e-5) ? 2.0 : 0.0)
                            + (fpEqual(u, u + 2e-4) ? 4.0 : 0.0);
                return float4(equal, pixelDist(uv * 3.0), sdf(4.0 * u),
                              ComputeCoverage(uv * 1.2, float2(u, v) * 1.5));
            #elif defined(UE_TEXT)
                float3 c3 = sd_to_coverage(float3(u - 0.5, v - 0.5, 0.0), uv * 2.0, 64.0, 2.0,
                                           float3(0.1, 0.0, -0.1), float3(0.0, 1.0, 2.0));
                float2 snapped = uie_snap_to_integer_pos(uv * 2.0 - 1.0);
                return float4(sd_to_coverage(u - 0.5, uv * 2.0, 1.0 / 64.0, 2.0, 0.1),
                              c3.x + 10.0 * c3.y, c3.z, snapped.x + 10.0 * snapped.y);
            #else // UE_SLOTS
                // Slot ids are 10 + 5 i; the pixel looks up id 10 + 5 floor(10 u) (slots 0..7, then
                // ids no slot has: 0).
                float id = 10.0 + 5.0 * floor(10.0 * u);
                half slot = FindTextureSlot(id);
                TextureInfo info = GetTextureInfo(slot);
                float4 texel = SampleTextureSlot((half)floor(8.0 * v), uv);
                float4 shaderInfo = SampleShaderInfo(half2(floor(u * 32.0) * 32.0 + 16.0, 0.0));
                return float4(slot + info.texelSize.x, texel.r + 2.0 * texel.g, info.textureId, shaderInfo.r);
            #endif
            }
            ENDCG
        }
    }
}
