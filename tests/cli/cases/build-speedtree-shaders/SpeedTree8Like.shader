// SPDX-License-Identifier: Apache-2.0
// A SpeedTree 8 tree shader in the style such shaders are written in: a Standard-lit surface
// program over SpeedTree8Common.cginc with its subsurface lighting model, the _WINDQUALITY_*
// keywords, the effect keywords and LOD fading. To keep the test short the lighting shortcuts are
// trimmed further than in SpeedTreeLike.shader (no shadows, no shadow caster: the keyword sets
// alone make 384 combinations) and LOD cross-fading is left to the other two shaders.
Shader "Case/SpeedTree8Like" {
    Properties {
        _MainTex ("Base (RGB) Transparency (A)", 2D) = "white" {}
        _Color ("Color", Color) = (1, 1, 1, 1)
        [Toggle(EFFECT_HUE_VARIATION)] _HueVariationKwToggle ("Hue Variation", Float) = 0
        _HueVariationColor ("Hue Variation Color", Color) = (1.0, 0.5, 0.0, 0.1)
        [Toggle(EFFECT_BUMP)] _NormalMapKwToggle ("Normal Mapping", Float) = 0
        _BumpMap ("Normal Map", 2D) = "bump" {}
        _Glossiness ("Smoothness", Range(0, 1)) = 0.1
        _Metallic ("Metallic", Range(0, 1)) = 0
        [Toggle(EFFECT_EXTRA_TEX)] _ExtraTexKwToggle ("Smoothness/Metallic/AO Map", Float) = 0
        _ExtraTex ("Smoothness (R), Metallic (G), AO (B)", 2D) = "(0.5, 0.0, 1.0)" {}
        [Toggle(EFFECT_SUBSURFACE)] _SubsurfaceKwToggle ("Subsurface", Float) = 0
        _SubsurfaceTex ("Subsurface (RGB)", 2D) = "white" {}
        _SubsurfaceColor ("Subsurface Color", Color) = (1, 1, 1, 1)
        _SubsurfaceIndirect ("Subsurface Indirect", Range(0, 1)) = 0.25
        [Toggle(EFFECT_BILLBOARD)] _BillboardKwToggle ("Billboard", Float) = 0
        _BillboardShadowFade ("Billboard Shadow Fade", Range(0, 1)) = 0.5
        [Enum(No, 2, Yes, 0)] _TwoSided ("Two Sided", Int) = 2
        [KeywordEnum(None, Fastest, Fast, Better, Best, Palm)] _WindQuality ("Wind Quality", Range(0, 5)) = 0
    }
    SubShader {
        Tags { "Queue" = "AlphaTest" "IgnoreProjector" = "True" "RenderType" = "TransparentCutout" "DisableBatching" = "LODFading" }
        LOD 400
        Cull [_TwoSided]

        CGPROGRAM
        #pragma surface SpeedTreeSurf SpeedTreeSubsurface vertex:SpeedTreeVert dithercrossfade nodirlightmap nodynlightmap noshadowmask nolightmap nofog noforwardadd novertexlights noshadow
        #pragma target 3.0
        #pragma instancing_options assumeuniformscaling maxcount:50
        #pragma shader_feature_local _WINDQUALITY_NONE _WINDQUALITY_FASTEST _WINDQUALITY_FAST _WINDQUALITY_BETTER _WINDQUALITY_BEST _WINDQUALITY_PALM
        #pragma shader_feature_local EFFECT_BILLBOARD
        #pragma shader_feature_local EFFECT_HUE_VARIATION
        #pragma shader_feature_local EFFECT_SUBSURFACE
        #pragma shader_feature_local EFFECT_BUMP
        #pragma shader_feature_local EFFECT_EXTRA_TEX
        #define ENABLE_WIND
        #include "SpeedTree8Common.cginc"
        ENDCG
    }
    FallBack "VertexLit"
}
