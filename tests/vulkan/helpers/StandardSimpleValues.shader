// SPDX-License-Identifier: Apache-2.0
// Evaluates functions of UnityStandardCoreForwardSimple.cginc and of UnityDeprecated.cginc
// (through UnityStandardBRDF.cginc) at every pixel of a full-target quad (pixel centre (u, v) as
// input, four floats per variant) for tests/vulkan/TextCoreSimpleValueTest.cpp.
Shader "Test/StandardSimpleValues" {
    SubShader {
        Pass {
            Cull Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile API_BRDF3 API_TANGENT_SPACE API_REFLECTIVITY API_VISIBILITY API_FRESNEL API_SPEC_POWER API_CG_DIRECTIONS
            #define _NORMALMAP 1
            #include "UnityStandardCoreForwardSimple.cginc"
            struct Interpolators {
                float4 pos : SV_POSITION;
                // Only what the fragment stage of the variant reads is passed on.
            #if defined(API_CG_DIRECTIONS)
                float4 dirs : TEXCOORD1;
            #else
                float2 uv : TEXCOORD0;
            #endif
            };
            Interpolators vert(float4 vertex : POSITION, float2 uv : TEXCOORD0) {
                Interpolators i;
                i.pos = float4(vertex.xy, 0.5, 1.0);
            #if !defined(API_CG_DIRECTIONS)
                i.uv = uv;
            #endif
                // UnityCG.cginc's directions of p = (u, v, 0.5, 1), linear in p, so the
                // interpolated value is the function of the pixel's uv.
            #if defined(API_CG_DIRECTIONS)
                float4 p = float4(uv, 0.5, 1.0);
                i.dirs = float4(WorldSpaceViewDir(p).x, ObjSpaceViewDir(p).y, WorldSpaceLightDir(p).x, ObjSpaceLightDir(p).x);
            #endif
                return i;
            }
            float4 frag(Interpolators i) : SV_Target {
            #if defined(API_CG_DIRECTIONS)
                return i.dirs;
            #else
                float u = i.uv.x, v = i.uv.y;
            #endif
            #if defined(API_BRDF3)
                return float4(BRDF3DirectSimple(half3(u, v, 0.2), half3(0.04 + 0.5 * v, 0.3, u), 0.1 + 0.5 * u, v), 0);
            #elif defined(API_TANGENT_SPACE)
                half3 n = normalize(half3(u - 0.5, 1.0, v - 0.5));
                half4 t = half4(1.0, 0.2 * u, 0.3 * v, v > 0.5 ? -1.0 : 1.0);
                half3 l, e;
                TangentSpaceLightingInput(n, t, half3(0.3, u, v), half3(v, -0.5, 0.2), l, e);
                return float4(l, e.y);
            #elif defined(API_REFLECTIVITY)
                return float4(MetallicSetup_Reflectivity() * u, SpecularSetup_Reflectivity() * v, RoughnessSetup_Reflectivity() * v, UNIFORM_REFLECTIVITY() * u);
            #elif defined(API_VISIBILITY)
                return float4(SmithGGXVisibilityTerm(u, v, 0.3 + 0.5 * u), CookTorranceVisibilityTerm(0.2 + 0.8 * u, 0.2 + 0.8 * v, 0.5 + 0.5 * v, 0.3 + 0.7 * u),
                              KelemenVisibilityTerm(0.3 + 0.7 * u), ModifiedKelemenVisibilityTerm(0.3 + 0.7 * v, u));
            #elif defined(API_FRESNEL)
                half3 f0 = half3(0.04, 0.5 * v, u);
                return float4(SebLagardeFresnelTerm(f0, u, v).yz, LazarovFresnelTerm(f0, v, u).xz);
            #elif !defined(API_CG_DIRECTIONS)
                half3 a = half3(u - 0.5, v, 0.2), b = normalize(half3(0.3, -0.4, 1.0));
                return float4(RDFBlinnPhongNormalizedTerm(u, 1.0 + 20.0 * v), RoughnessToSpecPower(0.2 + 0.8 * u), DotClamped(a, b) + LambertTerm(b, a), BlinnTerm(a, b));
            #endif
            }
            ENDCG
        }
    }
}
