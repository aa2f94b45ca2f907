// SPDX-License-Identifier: Apache-2.0
// varc built-in: TextCoreProperties.cginc. The material properties of the TextCore / TextMeshPro
// signed-distance-field text shaders (Unity 2022.3's name; TextCore_Properties.cginc is the 2021.3
// name and includes this file), declared once under one guard so that a shader can include
// either name, or both, with TextCore_SDF_SSD.cginc. Written for varc from the property names
// and the SDF technique; not derived from Unity's file.
#ifndef VARC_TEXTCORE_PROPERTIES_INCLUDED
#define VARC_TEXTCORE_PROPERTIES_INCLUDED

#include "HLSLSupport.cginc"

// Face: colour, dilation (SDF units) and an optional scrolling texture.
fixed4 _FaceColor;
float _FaceDilate;
sampler2D _FaceTex;
float _FaceUVSpeedX;
float _FaceUVSpeedY;

// Outline: colour, width and softness (SDF units), scrolling texture.
fixed4 _OutlineColor;
float _OutlineWidth;
float _OutlineSoftness;
sampler2D _OutlineTex;
float _OutlineUVSpeedX;
float _OutlineUVSpeedY;

// Bevel and lighting of the face (BEVEL_ON, the lit TextMeshPro variants).
float _Bevel;
float _BevelOffset;
float _BevelWidth;
float _BevelClamp;
float _BevelRoundness;
sampler2D _BumpMap;
float _BumpFace;
float _BumpOutline;
float _LightAngle;
fixed4 _SpecularColor;
float _SpecularPower;
float _Reflectivity;
float _Diffuse;
float _Ambient;

// Environment reflection (cube map rotated by _EnvMatrix).
samplerCUBE _Cube;
float4x4 _EnvMatrix;
float3 _EnvMatrixRotation;
fixed4 _ReflectFaceColor;
fixed4 _ReflectOutlineColor;

// Underlay (UNDERLAY_ON / UNDERLAY_INNER): a shifted, dilated, softened copy behind the face.
fixed4 _UnderlayColor;
float _UnderlayOffsetX;
float _UnderlayOffsetY;
float _UnderlayDilate;
float _UnderlaySoftness;

// Glow (GLOW_ON).
fixed4 _GlowColor;
float _GlowOffset;
float _GlowInner;
float _GlowOuter;
float _GlowPower;

// Font atlas: the SDF texture, its gradient scale (SDF spread in texels) and size; the weights
// of normal and bold glyphs; the ratios the font asset computes so that dilation, outline and
// underlay stay inside the gradient.
sampler2D _MainTex;
float _GradientScale;
float _TextureWidth;
float _TextureHeight;
float _WeightNormal;
float _WeightBold;
float _ScaleRatioA;
float _ScaleRatioB;
float _ScaleRatioC;
float _ShaderFlags;

// Vertex offset, screen-space scale and perspective correction of the SDF width.
float _VertexOffsetX;
float _VertexOffsetY;
float _ScaleX;
float _ScaleY;
float _PerspectiveFilter;
float _Sharpness;

// Masking: RectMask2D rectangle (UNITY_UI_CLIP_RECT) with soft edges, and the mask texture.
float4 _ClipRect;
float4 _MaskCoord;
float _MaskSoftnessX;
float _MaskSoftnessY;
float _MaskID;
sampler2D _MaskTex;

#endif // VARC_TEXTCORE_PROPERTIES_INCLUDED
