// SPDX-License-Identifier: Apache-2.0
// The shadow-caster and scene-editor passes of a particle shader in the style of Unity's
// Particles/Standard Unlit (our own text): UnityStandardParticleShadow.cginc with flipbook
// blending, alpha modes and metallic maps, and UnityStandardParticleEditor.cginc's selection and
// picking passes. builtin.standard-passes builds every variant.
Shader "varc-tests/ParticlesStandardLike" {
    Properties {
        _MainTex ("Albedo", 2D) = "white" {}
        _Color ("Colour", Color) = (1, 1, 1, 1)
        _Cutoff ("Alpha cutoff", Range(0, 1)) = 0.5
        _Metallic ("Metallic", Range(0, 1)) = 0
        _MetallicGlossMap ("Metallic", 2D) = "white" {}
    }
    SubShader {
        Tags { "RenderType" = "Opaque" "IgnoreProjector" = "True" "PreviewType" = "Plane" "PerformanceChecks" = "False" }

        Pass {
            Name "ShadowCaster"
            Tags { "LightMode" = "ShadowCaster" }
            BlendOp Add
            Blend One Zero
            ZWrite On
            Cull Off

            CGPROGRAM
            #pragma target 3.5
            #pragma shader_feature_local _ _ALPHATEST_ON _ALPHABLEND_ON _ALPHAPREMULTIPLY_ON _ALPHAMODULATE_ON
            #pragma shader_feature_local _METALLICGLOSSMAP
            #pragma shader_feature_local _REQUIRE_UV2
            #pragma multi_compile_shadowcaster
            #pragma multi_compile_instancing
            #pragma instancing_options procedural:vertInstancingSetup
            #pragma skip_variants _ALPHAMODULATE_ON SHADOWS_CUBE
            #pragma vertex vertParticleShadowCaster
            #pragma fragment fragParticleShadowCaster
            #include "UnityStandardParticleShadow.cginc"
            ENDCG
        }

        Pass {
            Name "SceneSelectionPass"
            Tags { "LightMode" = "SceneSelectionPass" }
            BlendOp Add
            Blend One Zero
            ZWrite On
            Cull Off

            CGPROGRAM
            #pragma target 2.5
            #pragma shader_feature_local _ALPHATEST_ON
            #pragma shader_feature_local _REQUIRE_UV2
            #pragma multi_compile_instancing
            #pragma instancing_options procedural:vertInstancingSetup
            #pragma vertex vertEditorPass
            #pragma fragment fragSceneHighlightPass
            #include "UnityStandardParticleEditor.cginc"
            ENDCG
        }

        Pass {
            Name "ScenePickingPass"
            Tags { "LightMode" = "Picking" }
            BlendOp Add
            Blend One Zero
            ZWrite On
            Cull Off

            CGPROGRAM
            #pragma target 2.5
            #pragma shader_feature_local _ALPHATEST_ON
            #pragma shader_feature_local _REQUIRE_UV2
            #pragma multi_compile_instancing
            #pragma instancing_options procedural:vertInstancingSetup
            #pragma vertex vertEditorPass
            #pragma fragment fragScenePickingPass
            #include "UnityStandardParticleEditor.cginc"
            ENDCG
        }
    }
}
