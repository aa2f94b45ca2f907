// SPDX-License-Identifier: Apache-2.0
// varc lighting library: forward rendering, one base pass plus one additive pass per extra pixel
// light, physically based (UNITY_BRDF_PBS). Technique of seed 000 ("Rendering 5: Multiple
// Lights"), written for varc.
//   ForwardBase: the main directional light, four per-vertex point lights (VERTEXLIGHT_ON,
//                Shade4PointLights) and spherical-harmonics ambient (ShadeSH9).
//   ForwardAdd:  one draw per additional pixel light, blended One One: POINT, DIRECTIONAL, SPOT,
//                POINT_COOKIE, DIRECTIONAL_COOKIE, with their shadow variants
//                (multi_compile_fwdadd_fullshadows); attenuation, cookies, shadows and the
//                shadow fade by UNITY_LIGHT_ATTENUATION.
//   Shadows are cast by the fallback's caster (shaders/builtin/fallback/VertexLit.shader).
// Math: docs/LIGHTING.md §8.1; bindings: docs/SHADER_ABI.md §7.
Shader "varc/Forward" {
    Properties {
        _Color ("Albedo colour", Color) = (1, 1, 1, 1)
        _MainTex ("Albedo (RGB)", 2D) = "white" {}
        _Metallic ("Metallic", Range(0, 1)) = 0
        _Smoothness ("Smoothness", Range(0, 1)) = 0.5
    }

    SubShader {
        Tags { "RenderType" = "Opaque" }

        Pass {
            Tags { "LightMode" = "ForwardBase" }

            CGPROGRAM
            #pragma target 3.0
            #pragma multi_compile _ VERTEXLIGHT_ON
            #pragma vertex ForwardVertex
            #pragma fragment ForwardFragment
            #define VARC_FORWARD_BASE 1
            #include "ForwardLighting.cginc"
            ENDCG
        }

        Pass {
            Tags { "LightMode" = "ForwardAdd" }
            Blend One One
            ZWrite Off

            CGPROGRAM
            #pragma target 3.0
            #pragma multi_compile_fwdadd_fullshadows
            #pragma vertex ForwardVertex
            #pragma fragment ForwardFragment
            #include "ForwardLighting.cginc"
            ENDCG
        }
    }
    Fallback "Legacy Shaders/VertexLit"
}
