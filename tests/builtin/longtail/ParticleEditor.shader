// SPDX-License-Identifier: Apache-2.0
// builtin.longtail-includes: the scene-view passes of a Standard particle shader
// (UnityStandardParticleEditor.cginc), with alpha test and flipbook blending keywords.
Shader "Test/Longtail/ParticleEditor" {
    Properties {
        _MainTex ("Albedo", 2D) = "white" {}
        _Cutoff ("Alpha Cutoff", Range(0, 1)) = 0.5
    }
    SubShader {
        Pass {
            Name "SceneSelectionPass"
            Tags { "LightMode" = "SceneSelectionPass" }
            CGPROGRAM
            #pragma vertex vertEditorPass
            #pragma fragment fragSceneHighlightPass
            #pragma shader_feature_local _ALPHATEST_ON
            #pragma shader_feature_local _REQUIRE_UV2
            #include "UnityStandardParticleEditor.cginc"
            ENDCG
        }
        Pass {
            Name "ScenePickingPass"
            Tags { "LightMode" = "Picking" }
            CGPROGRAM
            #pragma vertex vertEditorPass
            #pragma fragment fragScenePickingPass
            #pragma shader_feature_local _ALPHATEST_ON
            #pragma shader_feature_local _REQUIRE_UV2
            #include "UnityStandardParticleEditor.cginc"
            ENDCG
        }
    }
}
