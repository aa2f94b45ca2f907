// SPDX-License-Identifier: Apache-2.0
// Evaluates built-in API functions of the "hlslsupport" work (issue #27: UnityCG's depth-normal
// and directional-lightmap encodings, Lighting.cginc's light pre-pass and directional-lightmap
// functions, UnityShadowLibrary's tent weights, UnityShaderUtilities' ODS offset) at every pixel
// of a full-target quad, one group per variant, so that tests/vulkan/HlslSupportValueTest.cpp
// can compare lavapipe's result with the formula on the CPU. Pixel centre (u, v) in (0, 1)^2 is
// the input; each variant writes four floats.
Shader "Test/HlslSupportValues" {
    SubShader {
        Pass {
            Cull Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 3.0
            #pragma multi_compile HS_DEPTHNORMAL_ENC HS_DEPTHNORMAL_DEC HS_DIRLIGHTMAP HS_RNM HS_PREPASS HS_TENT3 HS_TENT5 HS_TENT7 HS_ODS HS_DXT5NM HS_DEFERRED HS_DEFERRED_GB HS_XFORM_VIEW HS_XFORM_CLIP HS_XFORM_VIEWCLIP HS_XFORM_DIR HS_XFORM_NORMAL HS_SCREEN HS_VIEWPROJ HS_SH HS_LIGHTDIR HS_FADE
            // The deferred group samples light probes, so indirect light reaches the surface.
            #if defined(HS_DEFERRED) || defined(HS_DEFERRED_GB)
            #define LIGHTPROBE_SH 1
            #endif
            #include "UnityCG.cginc"
            #include "Lighting.cginc"
            #include "UnityShadowLibrary.cginc"

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

            // A unit normal facing the viewer's side (z > 0) that varies over the quad.
            float3 testNormal(float u, float v) { return normalize(float3(u - 0.5, v - 0.5, 0.6 + 0.3 * u)); }

            float4 frag(Interpolators i) : SV_Target {
                float u = i.uv.x, v = i.uv.y;
            #if defined(HS_DEPTHNORMAL_ENC)
                return EncodeDepthNormal(u, testNormal(u, v));
            #elif defined(HS_DEPTHNORMAL_DEC)
                float depth;
                float3 n;
                DecodeDepthNormal(EncodeDepthNormal(v, testNormal(u, v)), depth, n);
                return float4(depth, n);
            #elif defined(HS_DIRLIGHTMAP)
                return float4(DecodeDirectionalLightmap(half3(u, v, 0.5), fixed4(u, 0.2, v, 0.25 + 0.5 * v), testNormal(v, u)), 0);
            #elif defined(HS_RNM)
                UNITY_DIRBASIS
                half3 scale;
                half3 lm = DirLightmapDiffuse(unity_DirBasis, fixed4(u, v, 0.5, 1), fixed4(0.2, v, u, 1), testNormal(u, v), u > 0.5, scale);
                return float4(lm, scale.y);
            #elif defined(HS_PREPASS)
                SurfaceOutput s = (SurfaceOutput)0;
                s.Albedo = half3(u, v, 0.5);
                s.Gloss = v;
                s.Alpha = 0.25;
                half4 light = half4(0.5 + u, v, 1.0 - u, 0.75 * u);
                fixed4 lambert = LightingLambert_PrePass(s, light);
                fixed4 blinn = LightingBlinnPhong_PrePass(s, light);
                return float4(lambert.r, blinn.g, blinn.b, blinn.a + lambert.a);
            #elif defined(HS_TENT3)
                float4 area, uncut, weight;
                _UnityInternalGetAreaPerTexel_3TexelsWideTriangleFilter(u - 0.5, area, uncut);
                _UnityInternalGetWeightPerTexel_3TexelsWideTriangleFilter(u - 0.5, weight);
                return float4(area.x, uncut.y, weight.z, weight.w + _UnityInternalGetAreaAboveFirstTexelUnderAIsocelesRectangleTriangle(1.0 + 2.0 * v));
            #elif defined(HS_TENT5)
                float3 a, b;
                _UnityInternalGetWeightPerTexel_5TexelsWideTriangleFilter(u - 0.5, a, b);
                return float4(a.x, a.z, b.x, b.z);
            #elif defined(HS_TENT7)
                float4 a, b;
                _UnityInternalGetWeightPerTexel_7TexelsWideTriangleFilter(v - 0.5, a, b);
                return float4(a.x, a.w, b.y, b.w);
            #elif defined(HS_ODS)
                // The test sets _WorldSpaceCameraPos = (0.25, -1, 0.5).
                return float4(ODSOffset(float3(u * 4.0 - 2.0, v, v * 3.0 - 1.0), 0.5 * (u - 0.5)), 0);
            #elif defined(HS_DEFERRED) || defined(HS_DEFERRED_GB)
                SurfaceOutput s = (SurfaceOutput)0;
                s.Albedo = half3(u, v, 0.5);
                s.Emission = half3(0.1, 0.2, u * v);
                s.Normal = testNormal(u, v);
                s.Gloss = v;
                s.Specular = u;
                UnityGI gi = (UnityGI)0;
                gi.indirect.diffuse = half3(0.5, u, v);
                half4 g0, g1, g2, b0, b1, b2;
                half4 lambert = LightingLambert_Deferred(s, gi, g0, g1, g2);
                half4 blinn = LightingBlinnPhong_Deferred(s, float3(0, 0, 1), gi, b0, b1, b2);
            #if defined(HS_DEFERRED)
                return float4(lambert.rgb, b1.a) + float4(0, 0, 0, g0.a + g1.a - 1.0);
            #else
                return float4(b1.rgb, b2.x) + float4(0, 0, 0, blinn.a - 1.0);
            #endif
            #elif defined(HS_XFORM_VIEW) || defined(HS_XFORM_CLIP) || defined(HS_XFORM_VIEWCLIP) || defined(HS_XFORM_DIR) || defined(HS_XFORM_NORMAL) || defined(HS_SCREEN) || defined(HS_VIEWPROJ)
                // Transforms with the matrices the test sets; p varies over the quad.
                float3 p = float3(u * 2.0 - 1.0, v, 0.5 - u);
            #if defined(HS_XFORM_VIEW)
                return float4(UnityObjectToViewPos(p).xy, UnityObjectToViewPos(float4(p, 1)).z, UnityWorldToViewPos(p).z);
            #elif defined(HS_XFORM_CLIP)
                return UnityWorldToClipPos(p);
            #elif defined(HS_XFORM_VIEWCLIP)
                return UnityViewToClipPos(p);
            #elif defined(HS_XFORM_DIR)
                return float4(UnityObjectToWorldDir(p), UnityWorldToObjectDir(p).x);
            #elif defined(HS_XFORM_NORMAL)
                return float4(UnityObjectToWorldNormal(p), UnityWorldSpaceViewDir(p).y);
            #elif defined(HS_SCREEN)
                float4 clip = float4(u * 2.0 - 1.0, v * 2.0 - 1.0, 0.3, 1.0 + u);
                return float4(ComputeScreenPos(clip).xy, ComputeNonStereoScreenPos(clip).w, ComputeGrabScreenPos(clip).y);
            #else
                return float4(TransformViewToProjection(p.xy), TransformViewToProjection(p).yz);
            #endif
            #elif defined(HS_SH)
                // The test sets the probe's SH coefficients.
                half4 n = half4(testNormal(u, v), 1.0);
                return float4(SHEvalLinearL0L1(n).r, SHEvalLinearL2(n).g, ShadeSH12Order(n).b,
                              ShadeSH3Order(n).r + SHEvalLinearL0L1_SampleProbeVolume(n, float3(u, v, 0)).g);
            #elif defined(HS_LIGHTDIR)
                // The test sets _WorldSpaceLightPos0 (a point light) and unity_LightShadowBias.x.
                float3 p = float3(u * 2.0 - 1.0, v, 0.5 - u);
                float4 clip = float4(u, v, v * 0.5, 1.0 + u);
                return float4(UnityWorldSpaceLightDir(p).xy, UnityApplyLinearShadowBias(clip).z, 0);
            #elif defined(HS_FADE)
                // The test sets unity_ShadowFadeCenterAndType and _LightShadowData.
                float3 p = float3(u * 4.0 - 2.0, v, 0.5 - u);
                float d = UnityComputeShadowFadeDistance(p, 3.0 * v);
                return float4(d, UnityComputeShadowFade(d), UnityComputeShadowFade(4.0 * u), 0);
            #else // HS_DXT5NM
                return float4(UnpackNormalDXT5nm(fixed4(0.3, v, 0.9, u)), 0);
            #endif
            }
            ENDCG
        }
    }
}
