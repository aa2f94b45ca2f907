// SPDX-License-Identifier: Apache-2.0
// Older and platform spellings of the built-in API (issue #27) used the way third-party shaders
// use them: DX9 rectangle samplers, uniform qualifiers, framebuffer inputs, generated-surface
// fog/TBN packing, Unity 4 collector and directional-lightmap helpers, forward shadows from a
// position, ODS and the shadow tent helpers (tests/builtin/CMakeLists.txt, builtin.instancing).
Shader "varc-tests/CompatMacros" {
    Properties { _MainTex ("Texture", 2D) = "white" {} }
    SubShader {
        Pass {
            Tags { "LightMode" = "ForwardAdd" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 3.0
            #pragma multi_compile_fwdadd_fullshadows
            #pragma multi_compile_fog
            #include "UnityCG.cginc"
            #include "AutoLight.cginc"
            #include "Lighting.cginc"

            SAMPLER_UNIFORM samplerRECT _MainTex;
            SHADER_UNIFORM float4 _MainTex_ST;
            UNITY_DECLARE_FRAMEBUFFER_INPUT_HALF(0);
            UNITY_DECLARE_TEX2DARRAY_MS(_Slices);
            UNITY_DECLARE_DEPTH_TEXTURE_MS(_DepthMS);

            struct v2f {
                float4 pos : SV_POSITION;
                float4 tSpace0 : TEXCOORD0;
                float4 tSpace1 : TEXCOORD1;
                float4 tSpace2 : TEXCOORD2;
                float4 worldPos : TEXCOORD3;
                float4 eyeVec : TEXCOORD4;
                UNITY_SHADOW_COORDS(5)
                float legacyFog : FOGC;
            };
            v2f vert(appdata_full v) {
                v2f o;
                UNITY_INITIALIZE_OUTPUT(v2f, o);
                o.pos = UnityObjectToClipPosODS(v.vertex.xyz) + UnityObjectToClipPos(v.vertex) * 0.0;
                float3 wp = mul(unity_ObjectToWorld, v.vertex).xyz + ODSOffset(v.vertex.xyz, 0.032) * 0.0;
                float3 n = UnityObjectToWorldNormal(v.normal);
                float3 t = UnityObjectToWorldDir(v.tangent.xyz);
                float3 b = cross(n, t) * v.tangent.w;
                o.tSpace0 = float4(t.x, b.x, n.x, wp.x);
                o.tSpace1 = float4(t.y, b.y, n.y, wp.y);
                o.tSpace2 = float4(t.z, b.z, n.z, wp.z);
                o.worldPos = float4(wp, 0);
                o.eyeVec = float4(wp - _WorldSpaceCameraPos, 0);
                o.legacyFog = o.pos.w;
                UNITY_TRANSFER_SHADOW(o, v.texcoord1.xy);
                UNITY_TRANSFER_FOG_COMBINED_WITH_TSPACE(o, o.pos);
                UNITY_TRANSFER_FOG_COMBINED_WITH_WORLD_POS(o, o.pos);
                UNITY_TRANSFER_FOG_COMBINED_WITH_EYE_VEC(o, o.pos);
                return o;
            }
            fixed4 frag(v2f i) : SV_Target {
                UNITY_EXTRACT_FOG_FROM_TSPACE(i);
                UNITY_RECONSTRUCT_TBN(i);
                float3 n = normalize(float3(_unity_tbn_0.z, _unity_tbn_1.z, _unity_tbn_2.z));
                float4 screen = ComputeScreenPos(UnityWorldToClipPos(i.worldPos.xyz));
                half shadow = UnityComputeForwardShadows(i.worldPos.xy, i.worldPos.xyz, screen);
                float4 sc = UNITY_READ_SHADOW_COORDS(i);
                UNITY_DIRBASIS
                half3 scales;
                half3 lm = DirLightmapDiffuse(unity_DirBasis, fixed4(1, 1, 1, 1), fixed4(1, 1, 1, 1), n, true, scales);
                float4 area, uncut, wA, wB;
                float3 w5A, w5B;
                _UnityInternalGetAreaPerTexel_3TexelsWideTriangleFilter(0.25, area, uncut);
                _UnityInternalGetWeightPerTexel_5TexelsWideTriangleFilter(0.25, w5A, w5B);
                _UnityInternalGetWeightPerTexel_7TexelsWideTriangleFilter(0.25, wA, wB);
                fixed4 c = texRECT(_MainTex, i.pos.xy * _MainTex_ST.xy) * UNITY_SAMPLE_1CHANNEL(_MainTex, i.pos.xy);
                c += UNITY_READ_FRAMEBUFFER_INPUT(0, i.pos) * 0.1 + _Slices.Load(int4(0, 0, 0, 0)) * 0.0
                   + _DepthMS.Load(int3(0, 0, 0)) * 0.0;
                c.rgb *= shadow * lm * (area.x + uncut.y + w5A.x + w5B.y + wA.z + wB.w + sc.x * 0.0
                       + _UnityInternalGetAreaAboveFirstTexelUnderAIsocelesRectangleTriangle(1.5));
                c.rgb *= (float)(UNITY_DISPLAY_ORIENTATION_PRETRANSFORM == UNITY_DISPLAY_ORIENTATION_PRETRANSFORM_0);
            #if defined(SPOT) && defined(SHADOWS_DEPTH)
                c.rgb *= UnitySampleShadowmap_PCF3x3Gaussian(sc, 0) + UnitySampleShadowmap_PCF5x5Gaussian(sc, 0);
            #endif
                c.a *= saturate(i.legacyFog);
                UNITY_APPLY_FOG(_unity_fogCoord, c);
                return c;
            }
            ENDCG
        }
        Pass {
            Tags { "LightMode" = "Deferred" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 3.0
            #include "Lighting.cginc"
            struct v2f { float4 pos : SV_POSITION; float3 n : TEXCOORD0; };
            v2f vert(appdata_base v) {
                v2f o;
                o.pos = UnityObjectToClipPos(v.vertex);
                o.n = UnityObjectToWorldNormal(v.normal);
                return o;
            }
            void frag(v2f i, out half4 g0 : SV_Target0, out half4 g1 : SV_Target1, out half4 g2 : SV_Target2, out half4 e : SV_Target3) {
                SurfaceOutput s = (SurfaceOutput)0;
                s.Albedo = 0.5; s.Normal = normalize(i.n); s.Gloss = 1; s.Specular = 0.5; s.Alpha = 1;
                UnityGI gi = (UnityGI)0;
                e = LightingBlinnPhong_Deferred(s, float3(0, 0, 1), gi, g0, g1, g2)
                  + LightingLambert_Deferred(s, gi, g0, g1, g2)
                  + LightingLambert_PrePass(s, half4(1, 1, 1, 1)) + LightingBlinnPhong_PrePass(s, half4(1, 1, 1, 1));
            }
            ENDCG
        }
        Pass {
            Tags { "LightMode" = "Always" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 3.0
            #define SHADOW_COLLECTOR_PASS
            #include "UnityCG.cginc"
            struct v2f { V2F_SHADOW_COLLECTOR; };
            v2f vert(appdata_base v) {
                v2f o;
                TRANSFER_SHADOW_COLLECTOR(o)
                return o;
            }
            fixed4 frag(v2f i) : SV_Target { SHADOW_COLLECTOR_FRAGMENT(i) }
            ENDCG
        }
    }
}
