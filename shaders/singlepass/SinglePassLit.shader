// SPDX-License-Identifier: Apache-2.0
// varc lighting library: single-pass forward lighting for a scriptable-pipeline-style renderer.
// Technique of seed 003 ("Scriptable Render Pipeline: Lights"), written for varc. Every object
// is drawn once; the frame's visible lights (up to 16) sit in one light buffer and each draw
// carries the indices of the lights that touch it: the first four are shaded per pixel, the next
// four per vertex. Diffuse only, albedo from the per-instance _Color; GPU instancing with
// multi_compile_instancing. Program: SinglePassLit.hlsl; math: docs/LIGHTING.md §8.4; light
// buffer layout: docs/SHADER_ABI.md §4.12.
Shader "varc/SinglePassLit" {
    Properties {
        _Color ("Albedo colour", Color) = (1, 1, 1, 1)
    }

    SubShader {
        Pass {
            HLSLPROGRAM
            #pragma target 3.5
            #pragma multi_compile_instancing
            #pragma vertex SinglePassVertex
            #pragma fragment SinglePassFragment
            #include "SinglePassLit.hlsl"
            ENDHLSL
        }
    }
}
