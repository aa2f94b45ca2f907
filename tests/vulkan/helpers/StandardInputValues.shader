// SPDX-License-Identifier: Apache-2.0
// Runs the material inputs of UnityStandardInput.cginc (texture coordinates, albedo, alpha,
// occlusion, emission, parallax, tangent-space normal, metallic / specular gloss) and the light
// helpers of UnityStandardCore.cginc over a full-target quad for
// tests/vulkan/StandardInputValueTest.cpp. The test binds solid textures of known texels (gray
// 128/255, bump (128, 128, 255, 255)/255); pixel centre (u, v) is the input.
Shader "Test/StandardInputValues" {
    SubShader {
        Pass {
            Cull Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 3.0
            #pragma multi_compile SI_TEXCOORDS SI_SURFACE SI_MAPS SI_NORMAL SI_LIGHTS
            // The map groups run with the Standard shader's map keywords on.
            #if defined(SI_MAPS) || defined(SI_NORMAL)
            #define _EMISSION 1
            #define _PARALLAXMAP 1
            #define _NORMALMAP 1
            #define _METALLICGLOSSMAP 1
            #endif
            #include "UnityStandardCore.cginc"

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
                float4 tc = float4(u, v, 1.0 - u, 0.5 * v);
            #if defined(SI_TEXCOORDS)
                VertexInput vi = (VertexInput)0;
                vi.uv0 = float2(u, v);
                vi.uv1 = float2(v, u);
                return TexCoords(vi);
            #elif defined(SI_SURFACE)
                return float4(Albedo(tc).g, Alpha(tc.xy), Occlusion(tc.xy), SpecularGloss(tc.xy).g + MetallicGloss(tc.xy).x + Emission(tc.xy).r);
            #elif defined(SI_MAPS)
                float4 p = Parallax(tc, normalize(half3(u - 0.5, v - 0.5, 0.5)));
                return float4(p.x, p.w, Emission(tc.xy).g, MetallicGloss(tc.xy).y);
            #elif defined(SI_NORMAL)
                return float4(NormalInTangentSpace(tc), SpecularGloss(tc.xy).a);
            #else // SI_LIGHTS
                UnityLight m = MainLight();
                UnityLight a = AdditiveLight(half3(u - 0.5, v - 0.5, 1.0), 0.5 + 0.5 * u);
                UnityLight d = DummyLight();
                UnityIndirect z = ZeroIndirect();
                half4 o = OutputForward(half4(u, v, 0.5, 0.3), 0.6);
                return float4(m.color.g + m.dir.x, a.dir.x, a.color.b,
                              o.a + d.dir.y + dot(d.color, 1) + dot(z.diffuse + z.specular, 1) + o.r - u);
            #endif
            }
            ENDCG
        }
    }
}
