// SPDX-License-Identifier: Apache-2.0
// Evaluates the small terms of UnityStandardBRDF, UnityStandardUtils, UnityImageBasedLighting,
// UnityGBuffer, Lighting and UnityGlobalIllumination (roughness conversions, GGX, Smith
// visibility, Disney diffuse, Fresnel, normal helpers, energy conservation, parallax, box
// projection, mip mapping, G-buffer packing, the legacy light models, the GI resets) at every
// pixel of a full-target quad, one group per variant, for tests/vulkan/StandardTermsValueTest.cpp.
// Pixel centre (u, v) in (0, 1)^2 is the input; each variant writes four floats.
Shader "Test/StandardTermsValues" {
    SubShader {
        Pass {
            Cull Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 3.0
            #pragma multi_compile ST_ROUGH ST_MICRO ST_FRESNEL ST_SAFENORM ST_BLEND ST_UNPACK ST_ENERGY ST_LERP ST_PARALLAX ST_BOX ST_MIP ST_GBUF_TO ST_GBUF_FROM ST_LEGACY ST_RESET ST_LAMBERT ST_ENVSURF ST_PREMUL ST_PREMUL_ON
            // The Transparent mode's keyword, in one variant (PreMultiplyAlpha tests it).
            #if defined(ST_PREMUL_ON)
            #define _ALPHAPREMULTIPLY_ON 1
            #endif
            #include "UnityStandardBRDF.cginc"
            #include "UnityStandardUtils.cginc"
            #include "UnityImageBasedLighting.cginc"
            #include "UnityGBuffer.cginc"
            #include "Lighting.cginc"
            #include "UnityPBSLighting.cginc"

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

            // A unit normal facing +z that varies over the quad.
            float3 testNormal(float u, float v) { return normalize(float3(u - 0.5, v - 0.5, 0.6 + 0.3 * u)); }

            float4 frag(Interpolators i) : SV_Target {
                float u = i.uv.x, v = i.uv.y;
            #if defined(ST_ROUGH)
                return float4(SmoothnessToPerceptualRoughness(u), PerceptualRoughnessToRoughness(v),
                              SmoothnessToRoughness(u), GGXTerm(u, 0.05 + 0.9 * v));
            #elif defined(ST_MICRO)
                return float4(SmithJointGGXVisibilityTerm(u, v, 0.1 + 0.8 * u * v),
                              DisneyDiffuse(v, u, 0.5 * (u + v), 1.0 - u * v),
                              SmithJointGGXVisibilityTerm(0.0, 0.0, v), GGXTerm(1.0, 0.2 + 0.5 * u));
            #elif defined(ST_FRESNEL)
                half3 f = FresnelTerm(half3(0.04, v, 0.5), u);
                return float4(f.yz, FresnelLerp(half3(u, 0.2, 0.1), half3(1.0, v, 0.5), v).xy);
            #elif defined(ST_SAFENORM)
                // Vectors from length 0 to 0.1: below sqrt(0.001) the length is clamped.
                float3 n = Unity_SafeNormalize(float3(u - 0.5, v - 0.5, 0.0) * 0.2);
                return float4(n, length(Unity_SafeNormalize(float3(u, v, 1.0))));
            #elif defined(ST_BLEND)
                return float4(BlendNormals(testNormal(u, v), testNormal(v, 1.0 - u)), 0);
            #elif defined(ST_UNPACK)
                half4 packed = half4(u, v, 0.5 + 0.5 * u, 0.7);
                return float4(UnpackScaleNormal(packed, 0.5 + v).xz, UnpackScaleNormalRGorAG(packed, 2.0 * u).yz);
            #elif defined(ST_ENERGY)
                half oneMinusReflectivity;
                half3 diffuse = EnergyConservationBetweenDiffuseAndSpecular(half3(u, v, 0.5), half3(0.1, 0.5 * v, 0.3 * u), oneMinusReflectivity);
                return float4(diffuse.xy, oneMinusReflectivity, SpecularStrength(half3(u, v, 0.5)));
            #elif defined(ST_PREMUL) || defined(ST_PREMUL_ON)
                half modifiedAlpha;
                half3 premultiplied = PreMultiplyAlpha(half3(u, v, 0.5), v, 0.3 + 0.5 * u, modifiedAlpha);
                return float4(premultiplied.xy, modifiedAlpha, 0);
            #elif defined(ST_LERP)
                half3 w = LerpWhiteTo(half3(u, v, 0.3), v);
                return float4(w.xz, LerpOneTo(u, v), OneMinusReflectivityFromMetallic(u));
            #elif defined(ST_PARALLAX)
                float2 offset = ParallaxOffset1Step(u, 0.5, normalize(float3(u - 0.5, v - 0.5, 0.3 + v)));
                // Nearly grazing views: the 0.42 bias keeps the shift finite.
                float2 grazing = ParallaxOffset1Step(1.0 - v, 0.1 + 0.2 * u, float3(0.7, -0.2, 0.01 * v));
                return float4(offset, grazing);
            #elif defined(ST_BOX)
                // A probe box [-2, 1.5] x [-1, 2] x [-1.5, 1] centred at (0.1, 0.2, 0.3); w = 0 (an
                // infinite probe) in the right half leaves the direction as it is.
                float3 refl = float3(u - 0.5, v - 0.5, 0.4 - v);
                float3 pos = float3(0.2 * u, 0.1, -0.3 * v);
                float4 centre = float4(0.1, 0.2, 0.3, u < 0.5 ? 1.0 : 0.0);
                return float4(BoxProjectedCubemapDirection(refl, pos, centre, float4(-2, -1, -1.5, 0), float4(1.5, 2, 1, 0)), 0);
            #elif defined(ST_MIP)
                Unity_GlossyEnvironmentData g = UnityGlossyEnvironmentSetup(v, testNormal(u, v), normalize(float3(0.2, u - 0.5, 1.0)), half3(0.04, 0.04, 0.04));
                return float4(perceptualRoughnessToMipmapLevel(u), mipmapLevelToPerceptualRoughness(6.0 * v), g.roughness, g.reflUVW.x);
            #elif defined(ST_GBUF_TO)
                UnityStandardData d;
                d.diffuseColor = half3(u, v, 0.5);
                d.occlusion = 1.0 - u;
                d.specularColor = half3(0.2, v, u);
                d.smoothness = 0.3 + 0.5 * v;
                d.normalWorld = testNormal(u, v);
                half4 g0, g1, g2;
                UnityStandardDataToGbuffer(d, g0, g1, g2);
                return float4(g0.a, g1.y + g1.w, g2.x, g2.y + g2.w);
            #elif defined(ST_LEGACY)
                SurfaceOutput o = (SurfaceOutput)0;
                o.Albedo = half3(u, v, 0.5);
                o.Normal = testNormal(u, v);
                o.Specular = 0.05 + 0.4 * v;
                o.Gloss = 0.25 + 0.5 * u;
                o.Alpha = 0.75;
                UnityLight light;
                light.color = half3(1.0, 0.5, 2.0);
                light.dir = normalize(half3(0.3, -0.4, 0.8));
                light.ndotl = 0;
                fixed4 lambert = UnityLambertLight(o, light);
                fixed4 blinn = UnityBlinnPhongLight(o, normalize(half3(u - 0.3, 0.2, 1.0)), light);
                return float4(lambert.r, blinn.g, blinn.b, lambert.a + blinn.a);
            #elif defined(ST_RESET)
                UnityGI gi;
                gi.light.color = half3(u, v, 1.0);
                gi.indirect.diffuse = half3(v, 1.0, u);
                gi.indirect.specular = half3(1.0, u, v);
                ResetUnityGI(gi);
                UnityLight light;
                ResetUnityLight(light);
                return float4(dot(gi.light.color, 1) + dot(gi.indirect.diffuse, 1) + dot(gi.indirect.specular, 1),
                              gi.light.dir.y + gi.light.ndotl, light.dir.y + dot(light.color, 1), light.ndotl + length(light.dir) * (u + 1.0) - u);
            #elif defined(ST_LAMBERT)
                float3 L;
                float NdotL, weightOverPdf;
                ImportanceSampleLambert(float2(u, v), float3(0, 0, 1), float3(1, 0, 0), float3(0, 1, 0), L, NdotL, weightOverPdf);
                return float4(L.xy, NdotL, weightOverPdf);
            #elif defined(ST_ENVSURF)
                SurfaceOutputStandard s = (SurfaceOutputStandard)0;
                s.Smoothness = v;
                s.Normal = normalize(float3(0.2, u - 0.5, 1.0));
                s.Albedo = half3(u, v, 0.5);
                s.Metallic = 0.5;
                UnityGIInput data = (UnityGIInput)0;
                data.worldViewDir = testNormal(u, v);
                UNITY_GLOSSY_ENV_FROM_SURFACE(g, s, data);
                return float4(g.roughness, g.reflUVW);
            #else // ST_GBUF_FROM
                UnityStandardData d = UnityStandardDataFromGbuffer(half4(u, v, 0.5, 0.25 + 0.5 * v), half4(0.1, u, v, 0.7), half4(u, v, 0.9, 1.0));
                return float4(d.normalWorld.xz, d.occlusion + d.specularColor.y, d.smoothness + d.diffuseColor.y);
            #endif
            }
            ENDCG
        }
    }
}
