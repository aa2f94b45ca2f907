// SPDX-License-Identifier: Apache-2.0
// varc lighting library: per-pixel Blinn-Phong lighting written in GLSL, with Unity's four
// per-vertex lights in the base pass. Technique of seed 001 ("GLSL Programming/Unity/Multiple
// Lights"), written for varc. One GLSLPROGRAM per pass, split into stages by #ifdef VERTEX /
// #ifdef FRAGMENT; built-ins come from UnityCG.glslinc and UnityLighting.glslinc.
//   ForwardBase: ambient (LIGHTPROBE_SH: ShadeSH9, else gl_LightModel.ambient), the main
//                directional light per pixel, unity_4LightPos*0 vertex lights (VERTEXLIGHT_ON).
//                multi_compile_fwdbase without the lightmap and shadow keywords this shader
//                does not implement (skip_variants).
//   ForwardAdd:  one draw per additional directional or point light, blended One One; the light
//                type is read from _WorldSpaceLightPos0.w, the range from _LightPositionRange.w.
// Math: docs/LIGHTING.md §8.2; bindings: docs/SHADER_ABI.md §4.11.
Shader "varc/GlslVertexLights" {
    Properties {
        _Color ("Diffuse colour", Color) = (1, 1, 1, 1)
        _SpecColor ("Specular colour", Color) = (1, 1, 1, 1)
        _Shininess ("Blinn-Phong exponent", Float) = 32
    }

    SubShader {
        Pass {
            Tags { "LightMode" = "ForwardBase" }

            GLSLPROGRAM
            #pragma multi_compile_fwdbase
            #pragma skip_variants LIGHTMAP_ON DIRLIGHTMAP_COMBINED DYNAMICLIGHTMAP_ON SHADOWS_SCREEN SHADOWS_SHADOWMASK LIGHTMAP_SHADOW_MIXING
            #define VARC_GLSL_BASE 1
            #include "GlslLighting.glslinc"
            ENDGLSL
        }

        Pass {
            Tags { "LightMode" = "ForwardAdd" }
            Blend One One
            ZWrite Off

            GLSLPROGRAM
            #include "GlslLighting.glslinc"
            ENDGLSL
        }
    }
}
