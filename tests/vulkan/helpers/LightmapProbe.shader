// SPDX-License-Identifier: Apache-2.0
// Shows what a lightmapped object's ForwardBase draw binds (tests/vulkan/ForwardRenderTest.cpp,
// LightmapBindingTest): rgb = the baked lightmap (directional with DIRLIGHTMAP_COMBINED, as
// UnityGI_Base decodes it) + the realtime lightmap; a = the shadow mask's first channel
// (SHADOWS_SHADOWMASK with LIGHTMAP_ON), halved with LIGHTMAP_SHADOW_MIXING.
Shader "Test/LightmapProbe" {
    SubShader {
        Pass {
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile_fwdbase
            #pragma skip_variants VERTEXLIGHT_ON SHADOWS_SCREEN LIGHTPROBE_SH
            #include "UnityCG.cginc"

            struct Interpolators {
                float4 pos : SV_POSITION;
                float4 lightmapUV : TEXCOORD0;
                float3 normal : TEXCOORD1;
            };

            Interpolators vert(float4 vertex : POSITION, float3 normal : NORMAL,
                               float2 uv1 : TEXCOORD1, float2 uv2 : TEXCOORD2) {
                Interpolators o;
                o.pos = UnityObjectToClipPos(vertex);
                o.lightmapUV.xy = uv1 * unity_LightmapST.xy + unity_LightmapST.zw;
                o.lightmapUV.zw = uv2 * unity_DynamicLightmapST.xy + unity_DynamicLightmapST.zw;
                o.normal = UnityObjectToWorldNormal(normal);
                return o;
            }

            float4 frag(Interpolators i) : SV_Target {
                float3 n = normalize(i.normal);
                float3 c = 0;
                // 1 for any finite input: every variant reads both interpolators (validation
                // warns about outputs the fragment stage does not consume).
                float mask = step(-1e30, i.lightmapUV.x + i.lightmapUV.z + n.x);
            #if defined(LIGHTMAP_ON)
                float3 baked = DecodeLightmap(UNITY_SAMPLE_TEX2D(unity_Lightmap, i.lightmapUV.xy));
              #if defined(DIRLIGHTMAP_COMBINED)
                float4 direction =
                    UNITY_SAMPLE_TEX2D_SAMPLER(unity_LightmapInd, unity_Lightmap, i.lightmapUV.xy);
                baked = DecodeDirectionalLightmap(baked, direction, n);
              #endif
                c += baked;
              #if defined(SHADOWS_SHADOWMASK)
                mask *= UNITY_SAMPLE_TEX2D(unity_ShadowMask, i.lightmapUV.xy).r;
              #endif
            #endif
            #if defined(DYNAMICLIGHTMAP_ON)
                float4 realtime = UNITY_SAMPLE_TEX2D(unity_DynamicLightmap, i.lightmapUV.zw);
                c += DecodeRealtimeLightmap(realtime);
            #endif
            #if defined(LIGHTMAP_SHADOW_MIXING)
                mask *= 0.5;
            #endif
                return float4(c, mask);
            }
            ENDCG
        }
    }
}
