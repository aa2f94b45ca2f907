// SPDX-License-Identifier: Apache-2.0
// Runs AutoLight.cginc's light-coordinate plumbing and attenuation (LIGHTING_COORDS,
// TRANSFER_VERTEX_TO_FRAGMENT, LIGHT_ATTENUATION, UnitySpotCookie, UnitySpotAttenuate) for each
// light type over a full-target quad, for tests/vulkan/AutoLightValueTest.cpp. The object and
// light matrices are identities, so the light coordinate is the vertex the fragment builds: one
// that samples the centre of texel (floor(4 s), floor(4 t)) of the 4 x 4 textures the test binds
// (no shadows: SHADOW_ATTENUATION is 1).
Shader "Test/AutoLightValues" {
    SubShader {
        Pass {
            Cull Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile POINT SPOT DIRECTIONAL POINT_COOKIE DIRECTIONAL_COOKIE
            #include "UnityCG.cginc"
            #include "AutoLight.cginc"

            struct Interpolators {
                float4 pos : SV_POSITION;
                float2 uv : TEXCOORD0;
            };
            struct LightInput {
                LIGHTING_COORDS(1, 2)
                float unused : TEXCOORD3;
            };

            Interpolators vert(float4 vertex : POSITION, float2 uv : TEXCOORD0) {
                Interpolators i;
                i.pos = float4(vertex.xy, 0.5, 1.0);
                i.uv = uv;
                return i;
            }

            float4 frag(Interpolators i) : SV_Target {
                float2 centre = (floor(i.uv * 4.0) + 0.5) / 4.0;
                appdata_base v = (appdata_base)0;
            #if defined(POINT) || defined(POINT_COOKIE)
                // dot(lc, lc) = centre.x: the falloff texel (x, x).
                v.vertex = float4(sqrt(centre.x), 0.0, 0.0, 1.0);
            #elif defined(SPOT)
                // The cookie at centre; dot(lc.xyz, lc.xyz) = 0.375 (falloff texel (1, 1)); the top
                // quarter is behind the light (z < 0).
                float2 xy = centre - 0.5;
                float z = sqrt(0.375 - dot(xy, xy)) * (i.uv.y > 0.75 ? -1.0 : 1.0);
                v.vertex = float4(xy, z, 1.0);
            #else
                v.vertex = float4(centre, 0.0, 1.0);
            #endif
                LightInput a = (LightInput)0;
                TRANSFER_VERTEX_TO_FRAGMENT(a);
                float atten = LIGHT_ATTENUATION(a);
            #if defined(SPOT)
                return float4(atten, UnitySpotCookie(a._LightCoord), UnitySpotAttenuate(a._LightCoord.xyz), a._LightCoord.z);
            #else
                return float4(atten, i.uv.x, 0.0, 0.0);
            #endif
            }
            ENDCG
        }
    }
}
