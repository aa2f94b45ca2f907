// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityUIE.cginc (Unity 2019.4-2021.3). UI Toolkit's runtime shader: the vertex
// layout the UI renderer emits, its per-element data (transforms, clip rects, opacity and colour
// pages, read from constants or the shader-info texture), texture slots, gradients, text and the
// standard vertex / fragment programs (vert / frag unless UIE_CUSTOM_SHADER). Written for varc
// from the documented behaviour; the layout of the data textures is varc's own.
//
// The vertex layout is 2021.3's (appdata_t ids / flags / opacityColorPages / circle / textureId,
// v2f pos / uvClip / typeTexSettings / ...); the older releases' differently named members sharing
// the same semantics cannot coexist with it. Functions of older releases whose parameters differ
// (uie_std_vert_shader_info, vert with clipSpacePos, sdf, TestForValue, uie_get_border_offset)
// are provided too.
#ifndef UNITY_UIE_INCLUDED
#define UNITY_UIE_INCLUDED

#include "UnityCG.cginc"

#define JOIN2(a, b) a##b

// Configuration, each overridable before the include (EditorUIE.cginc does).
#ifndef UIE_SKIN_ELEMS_COUNT_MAX_CONSTANTS
#define UIE_SKIN_ELEMS_COUNT_MAX_CONSTANTS 20
#endif
#ifndef UIE_TEXTURE_SLOT_SIZE
#define UIE_TEXTURE_SLOT_SIZE 2  // float4s of _TextureInfo per slot
#endif
#if SHADER_TARGET < 35
#define UIE_FLAT_OPTIM
#define UIE_SIMPLE_ATLAS 1
#define UIE_TEXTURE_SLOT_COUNT 4
#else
#define UIE_FLAT_OPTIM nointerpolation
#define UIE_SIMPLE_ATLAS 0
#define UIE_TEXTURE_SLOT_COUNT 8
#endif
#if SHADER_TARGET >= 30
#define UIE_SHADER_INFO_IN_VS 1
#else
#define UIE_SHADER_INFO_IN_VS 0
#endif
#ifndef UIE_NOINTERPOLATION
#if defined(UNITY_PLATFORM_WEBGL)
#define UIE_NOINTERPOLATION
#else
#define UIE_NOINTERPOLATION nointerpolation
#endif
#endif
#ifndef UIE_COLORSPACE_GAMMA
#if defined(UNITY_COLORSPACE_GAMMA)
#define UIE_COLORSPACE_GAMMA 1
#else
#define UIE_COLORSPACE_GAMMA 0
#endif
#endif
// Gamma-space UI fits 8-bit precision; linear-space UI needs half.
#if UIE_COLORSPACE_GAMMA
#ifndef UIE_FRAG_T
#define UIE_FRAG_T fixed4
#endif
#ifndef UIE_FRAG_SCALAR_T
#define UIE_FRAG_SCALAR_T fixed
#endif
#define UIE_V2F_COLOR_T fixed4
#else
#ifndef UIE_FRAG_T
#define UIE_FRAG_T half4
#endif
#ifndef UIE_FRAG_SCALAR_T
#define UIE_FRAG_SCALAR_T half
#endif
#define UIE_V2F_COLOR_T half4
#endif

// Z of the mesh and of the stencil mask geometry.
static const float kUIEMeshZ = 0.0;
static const float kUIEMaskZ = 1.0;
static const float kUIEVertexLastFlagValue = 10.0;  // the largest vertex flag of 2019.4 / 2020.3

struct appdata_t {
    float4 vertex : POSITION;
    float4 color : COLOR;
    float2 uv : TEXCOORD0;
    float4 xformClipPages : TEXCOORD1;     // transform page (xy), clip-rect page (zw)
    float4 ids : TEXCOORD2;                // transform, clip rect, opacity, colour ids (* 255)
    float4 flags : TEXCOORD3;              // render type (x) and settings index (yz) (* 255)
    float4 opacityColorPages : TEXCOORD4;  // opacity page (xy), colour page (zw)
    float4 circle : TEXCOORD5;             // rounded-corner arcs: outer (xy), inner (zw)
    float textureId : TEXCOORD6;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

struct v2f {
    float4 pos : SV_POSITION;
    UIE_V2F_COLOR_T color : COLOR;
    float4 uvClip : TEXCOORD0;  // uv (xy), position relative to the clip rect (zw)
    UIE_FLAT_OPTIM half4 typeTexSettings : TEXCOORD1;  // type, texture slot, settings index, -
    UIE_FLAT_OPTIM fixed4 clipRectOpacityUVs : TEXCOORD2;
    UIE_FLAT_OPTIM float2 colorUVs : TEXCOORD3;
    half4 circle : TEXCOORD4;
    UNITY_VERTEX_OUTPUT_STEREO
};

struct GradientLocation {
    float4 location;  // the gradient's texels in the atlas: x, y, width, height
    float2 uv;
};

struct TextureInfo {
    float textureId;
    float unused;
    float2 texelSize;
};

// Per-element data: in the shader-info texture, or (without vertex texture fetch) in constants.
sampler2D_float _ShaderInfoTex;
float4 _ShaderInfoTex_TexelSize;
float4 _Transforms[UIE_SKIN_ELEMS_COUNT_MAX_CONSTANTS * 3];
float4 _ClipRects[UIE_SKIN_ELEMS_COUNT_MAX_CONSTANTS];
float4 _ClipSpaceParams;  // half the viewport size in pixels (xy) and its inverse (zw)
float4 _TextureInfo[UIE_TEXTURE_SLOT_COUNT * UIE_TEXTURE_SLOT_SIZE];
sampler2D _Texture0;
float4 _Texture0_ST;
sampler2D _Texture1;
float4 _Texture1_ST;
sampler2D _Texture2;
float4 _Texture2_ST;
sampler2D _Texture3;
float4 _Texture3_ST;
#if UIE_TEXTURE_SLOT_COUNT == 8
sampler2D _Texture4;
float4 _Texture4_ST;
sampler2D _Texture5;
float4 _Texture5_ST;
sampler2D _Texture6;
float4 _Texture6_ST;
sampler2D _Texture7;
float4 _Texture7_ST;
#endif
sampler2D _FontTex;
float4 _FontTex_ST;
float4 _FontTex_TexelSize;
float _FontTexSDFScale;
sampler2D _GradientSettingsTex;
float4 _GradientSettingsTex_ST;
float4 _GradientSettingsTex_TexelSize;
// Values of older releases (2019.4 / 2020.3), kept so that shaders written for them build.
sampler2D _CustomTex;
float4 _CustomTex_ST;
float4 _CustomTex_TexelSize;
float4 _1PixelClipInvView;
float4 _PixelClipRect;
float4 _ScreenClipRect;
SamplerState uie_point_clamp_sampler;
SamplerState uie_linear_clamp_sampler;

// The element's transform (object to world), set by uie_vert_load_payload.
static float4x4 uie_toWorldMat;

#include "VarcUIECommon.cginc"

#endif  // UNITY_UIE_INCLUDED
