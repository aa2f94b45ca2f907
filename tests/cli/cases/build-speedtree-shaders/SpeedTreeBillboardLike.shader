// SPDX-License-Identifier: Apache-2.0
// A SpeedTree (7) billboard shader in the style such shaders are written in: the far LOD of a
// tree, a surface program over SpeedTreeBillboardCommon.cginc facing the camera position or
// direction, with bump, hue and cross-fade keywords (lighting shortcuts trimmed as in
// SpeedTreeLike.shader).
Shader "Case/SpeedTreeBillboardLike" {
    Properties {
        _Color ("Main Color", Color) = (1, 1, 1, 1)
        _HueVariation ("Hue Variation", Color) = (1.0, 0.5, 0.0, 0.1)
        _MainTex ("Base (RGB) Trans (A)", 2D) = "white" {}
        _BumpMap ("Normal Map", 2D) = "bump" {}
        _Cutoff ("Alpha Cutoff", Range(0, 1)) = 0.333
        [MaterialEnum(None, 0, Fastest, 1)] _WindQuality ("Wind Quality", Range(0, 1)) = 0
    }
    SubShader {
        Tags { "Queue" = "AlphaTest" "IgnoreProjector" = "True" "RenderType" = "TransparentCutout" "DisableBatching" = "LODFading" }
        LOD 400

        CGPROGRAM
        #pragma surface surf Lambert vertex:SpeedTreeBillboardVert nodirlightmap nodynlightmap noshadowmask dithercrossfade addshadow nolightmap nofog noforwardadd novertexlights
        #pragma target 3.0
        #pragma multi_compile __ BILLBOARD_FACE_CAMERA_POS
        #pragma multi_compile __ LOD_FADE_CROSSFADE
        #pragma shader_feature EFFECT_BUMP
        #pragma shader_feature EFFECT_HUE_VARIATION
        #define ENABLE_WIND
        #include "SpeedTreeBillboardCommon.cginc"

        void surf(Input IN, inout SurfaceOutput OUT) {
            SpeedTreeFragOut o;
            SpeedTreeFrag(IN, o);
            SPEEDTREE_COPY_FRAG(OUT, o)
        }
        ENDCG
    }
    FallBack "Transparent/Cutout/VertexLit"
}
