// SPDX-License-Identifier: Apache-2.0
// A TextCore SDF text shader in the usual shape of TextMeshPro / TextCore distance-field shaders:
// the properties, the UI stencil and clipping keywords, and the entry points of
// TextCore_SDF_SSD.cginc. builtin.textcore-glsl builds every variant. Written for varc's tests.
Shader "varc-tests/TextCoreSdf" {
    Properties {
        _FaceColor ("Face colour", Color) = (1, 1, 1, 1)
        _FaceDilate ("Face dilate", Range(-1, 1)) = 0
        _OutlineColor ("Outline colour", Color) = (0, 0, 0, 1)
        _OutlineWidth ("Outline thickness", Range(0, 1)) = 0
        _OutlineSoftness ("Outline softness", Range(0, 1)) = 0
        _UnderlayColor ("Underlay colour", Color) = (0, 0, 0, 0.5)
        _UnderlayOffsetX ("Underlay offset x", Range(-1, 1)) = 0
        _UnderlayOffsetY ("Underlay offset y", Range(-1, 1)) = 0
        _UnderlayDilate ("Underlay dilate", Range(-1, 1)) = 0
        _UnderlaySoftness ("Underlay softness", Range(0, 1)) = 0
        _GlowColor ("Glow colour", Color) = (0, 1, 0, 0.5)
        _GlowOffset ("Glow offset", Range(-1, 1)) = 0
        _GlowInner ("Glow inner", Range(0, 1)) = 0.05
        _GlowOuter ("Glow outer", Range(0, 1)) = 0.05
        _GlowPower ("Glow power", Range(1, 0)) = 0.75
        _WeightNormal ("Weight normal", Float) = 0
        _WeightBold ("Weight bold", Float) = 0.5
        _ShaderFlags ("Flags", Float) = 0
        _ScaleRatioA ("Scale ratio A", Float) = 1
        _ScaleRatioB ("Scale ratio B", Float) = 1
        _ScaleRatioC ("Scale ratio C", Float) = 1
        _MainTex ("Font atlas", 2D) = "white" {}
        _TextureWidth ("Texture width", Float) = 512
        _TextureHeight ("Texture height", Float) = 512
        _GradientScale ("Gradient scale", Float) = 5
        _Sharpness ("Sharpness", Range(-1, 1)) = 0
        _VertexOffsetX ("Vertex offset x", Float) = 0
        _VertexOffsetY ("Vertex offset y", Float) = 0
        _ClipRect ("Clip rect", Vector) = (-32767, -32767, 32767, 32767)
        _MaskSoftnessX ("Mask softness x", Float) = 0
        _MaskSoftnessY ("Mask softness y", Float) = 0
        _StencilComp ("Stencil comparison", Float) = 8
        _Stencil ("Stencil ID", Float) = 0
        _StencilOp ("Stencil operation", Float) = 0
        _StencilWriteMask ("Stencil write mask", Float) = 255
        _StencilReadMask ("Stencil read mask", Float) = 255
        _ColorMask ("Colour mask", Float) = 15
    }

    SubShader {
        Tags { "Queue" = "Transparent" "IgnoreProjector" = "True" "RenderType" = "Transparent" }
        Stencil {
            Ref [_Stencil]
            Comp [_StencilComp]
            Pass [_StencilOp]
            ReadMask [_StencilReadMask]
            WriteMask [_StencilWriteMask]
        }
        Cull Off
        ZWrite Off
        Lighting Off
        Fog { Mode Off }
        ZTest [unity_GUIZTestMode]
        Blend One OneMinusSrcAlpha
        ColorMask [_ColorMask]

        Pass {
            CGPROGRAM
            #pragma vertex VertShader
            #pragma fragment PixShader
            #pragma shader_feature __ OUTLINE_ON
            #pragma shader_feature __ UNDERLAY_ON UNDERLAY_INNER
            #pragma shader_feature __ GLOW_ON
            #pragma multi_compile __ UNITY_UI_CLIP_RECT
            #pragma multi_compile __ UNITY_UI_ALPHACLIP
            #include "UnityCG.cginc"
            #include "UnityUI.cginc"
            #include "TextCoreProperties.cginc"
            #include "TextCore_SDF_SSD.cginc"
            ENDCG
        }
    }
}
