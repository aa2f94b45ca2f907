// SPDX-License-Identifier: Apache-2.0
// varc lighting library: a plain Lambert diffuse shader with one base and one additive pass,
// built on the legacy AutoLight macros (LIGHTING_COORDS, TRANSFER_VERTEX_TO_FRAGMENT,
// LIGHT_ATTENUATION). Technique of seed 004 ("Writing Multi-Light Pixel Shaders in Unity"),
// written for varc, in linear colour: no x2 factors (LIGHTING.md §8.5 explains why).
//   ForwardBase: ambient (LIGHTPROBE_SH: ShadeSH9, else UNITY_LIGHTMODEL_AMBIENT), the main
//                directional light with its screen-space shadow (SHADOWS_SCREEN), four vertex
//                lights (VERTEXLIGHT_ON); multi_compile_fwdbase without the lightmap keywords.
//   ForwardAdd:  one draw per additional pixel light, Blend One One, all five light types with
//                their shadows (multi_compile_fwdadd_fullshadows).
// Program: SimpleDiffuse.cginc; math: docs/LIGHTING.md §8.5.
Shader "varc/SimpleDiffuse" {
    Properties {
        _Color ("Colour", Color) = (1, 1, 1, 1)
        _MainTex ("Albedo (RGB)", 2D) = "white" {}
    }

    SubShader {
        Tags { "Queue" = "Geometry" "RenderType" = "Opaque" }

        Pass {
            Tags { "LightMode" = "ForwardBase" }

            CGPROGRAM
            #pragma multi_compile_fwdbase
            #pragma skip_variants LIGHTMAP_ON DIRLIGHTMAP_COMBINED DYNAMICLIGHTMAP_ON SHADOWS_SHADOWMASK LIGHTMAP_SHADOW_MIXING
            #pragma vertex SimpleVertex
            #pragma fragment SimpleFragment
            #define VARC_SIMPLE_BASE 1
            #include "SimpleDiffuse.cginc"
            ENDCG
        }

        Pass {
            Tags { "LightMode" = "ForwardAdd" }
            Blend One One
            ZWrite Off

            CGPROGRAM
            #pragma multi_compile_fwdadd_fullshadows
            #pragma vertex SimpleVertex
            #pragma fragment SimpleFragment
            #include "SimpleDiffuse.cginc"
            ENDCG
        }
    }
    // Shadows are cast by the fallback's caster (shaders/builtin/fallback/VertexLit.shader).
    Fallback "Legacy Shaders/VertexLit"
}
