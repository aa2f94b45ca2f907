// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityCG.cginc. Unity's common helper library for CG/HLSL programs: transforms,
// view/light directions, vertex lights (Shade4PointLights), spherical harmonics (ShadeSH9),
// screen positions and depth, packing, fog and shadow-caster macros. Written for varc from the
// documented formulas (docs/LIGHTING.md, docs/SHADER_ABI.md); not derived from Unity.
#ifndef UNITY_CG_INCLUDED
#define UNITY_CG_INCLUDED

#include "HLSLSupport.cginc"
#include "UnityShaderVariables.cginc"
#include "UnityInstancing.cginc"

#define UNITY_PI 3.14159265359f
#define UNITY_TWO_PI 6.28318530718f
#define UNITY_FOUR_PI 12.56637061436f
#define UNITY_INV_PI 0.31830988618f
#define UNITY_INV_TWO_PI 0.15915494309f
#define UNITY_INV_FOUR_PI 0.07957747155f
#define UNITY_HALF_PI 1.57079632679f
#define UNITY_INV_HALF_PI 0.636619772367f

// varc renders in linear colour space (UNITY_COLORSPACE_GAMMA is never defined by the driver).
#ifdef UNITY_COLORSPACE_GAMMA
#define unity_ColorSpaceGrey fixed4(0.5, 0.5, 0.5, 0.5)
#define unity_ColorSpaceDouble fixed4(2.0, 2.0, 2.0, 2.0)
#define unity_ColorSpaceDielectricSpec half4(0.220916301, 0.220916301, 0.220916301, 1.0 - 0.220916301)
#define unity_ColorSpaceLuminance half4(0.22, 0.707, 0.071, 0.0)
#else
#define unity_ColorSpaceGrey fixed4(0.214041144, 0.214041144, 0.214041144, 0.5)
#define unity_ColorSpaceDouble fixed4(4.59479380, 4.59479380, 4.59479380, 2.0)
// Dielectric F0 = 4 % (linear); a = 1 - F0. Used by DiffuseAndSpecularFromMetallic.
#define unity_ColorSpaceDielectricSpec half4(0.04, 0.04, 0.04, 1.0 - 0.04)
#define unity_ColorSpaceLuminance half4(0.0396819152, 0.458021790, 0.00609653955, 1.0)
#endif

// ---------------------------------------------------------------------------------------------
// Standard vertex inputs.
// ---------------------------------------------------------------------------------------------
struct appdata_base {
    float4 vertex : POSITION;
    float3 normal : NORMAL;
    float4 texcoord : TEXCOORD0;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};
struct appdata_tan {
    float4 vertex : POSITION;
    float4 tangent : TANGENT;
    float3 normal : NORMAL;
    float4 texcoord : TEXCOORD0;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};
struct appdata_full {
    float4 vertex : POSITION;
    float4 tangent : TANGENT;
    float3 normal : NORMAL;
    float4 texcoord : TEXCOORD0;
    float4 texcoord1 : TEXCOORD1;
    float4 texcoord2 : TEXCOORD2;
    float4 texcoord3 : TEXCOORD3;
    fixed4 color : COLOR;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};
struct appdata_img {
    float4 vertex : POSITION;
    half2 texcoord : TEXCOORD0;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

// Legacy (Unity 4) macro: the object-space normal of a vertex input named `v`.
#define SCALED_NORMAL v.normal

// Object-space tangent frame of a vertex input named `v` (needs tangent and normal).
#define TANGENT_SPACE_ROTATION \
    float3 binormal = cross(normalize(v.normal), normalize(v.tangent.xyz)) * v.tangent.w; \
    float3x3 rotation = float3x3(v.tangent.xyz, binormal, v.normal)

// ---------------------------------------------------------------------------------------------
// Colour space. Exact sRGB transfer functions (IEC 61966-2-1).
// ---------------------------------------------------------------------------------------------
inline float GammaToLinearSpaceExact(float value) {
    if (value <= 0.04045F) return value / 12.92F;
    if (value < 1.0F) return pow((value + 0.055F) / 1.055F, 2.4F);
    return pow(value, 2.2F);
}
inline half3 GammaToLinearSpace(half3 sRGB) {
    return half3(GammaToLinearSpaceExact(sRGB.r), GammaToLinearSpaceExact(sRGB.g), GammaToLinearSpaceExact(sRGB.b));
}
inline float LinearToGammaSpaceExact(float value) {
    if (value <= 0.0F) return 0.0F;
    if (value <= 0.0031308F) return 12.92F * value;
    if (value < 1.0F) return 1.055F * pow(value, 0.4166667F) - 0.055F;
    return pow(value, 0.45454545F);
}
inline half3 LinearToGammaSpace(half3 linRGB) {
    return half3(LinearToGammaSpaceExact(linRGB.r), LinearToGammaSpaceExact(linRGB.g), LinearToGammaSpaceExact(linRGB.b));
}
// Rec. 709 luminance of a linear colour.
inline half LinearRgbToLuminance(half3 linearRgb) { return dot(linearRgb, half3(0.2126729f, 0.7151522f, 0.0721750f)); }
inline half Luminance(half3 rgb) { return dot(rgb, unity_ColorSpaceLuminance.rgb); }

// ---------------------------------------------------------------------------------------------
// Transforms. mul(M, v) with column vectors; matrices as documented in SHADER_ABI.md.
// ---------------------------------------------------------------------------------------------
// UnityObjectToClipPos: UnityShaderUtilities.cginc (via UnityShaderVariables.cginc).
inline float4 UnityWorldToClipPos(in float3 pos) { return mul(UNITY_MATRIX_VP, float4(pos, 1.0)); }
inline float4 UnityViewToClipPos(in float3 pos) { return mul(UNITY_MATRIX_P, float4(pos, 1.0)); }
inline float3 UnityObjectToViewPos(in float3 pos) {
    return mul(UNITY_MATRIX_V, mul(unity_ObjectToWorld, float4(pos, 1.0))).xyz;
}
inline float3 UnityObjectToViewPos(float4 pos) { return UnityObjectToViewPos(pos.xyz); }
inline float3 UnityWorldToViewPos(in float3 pos) { return mul(UNITY_MATRIX_V, float4(pos, 1.0)).xyz; }

inline float3 UnityObjectToWorldDir(in float3 dir) { return normalize(mul((float3x3)unity_ObjectToWorld, dir)); }
inline float3 UnityWorldToObjectDir(in float3 dir) { return normalize(mul((float3x3)unity_WorldToObject, dir)); }
// Normals transform with the inverse transpose: n_world = n_object * (WorldToObject)3x3.
inline float3 UnityObjectToWorldNormal(in float3 norm) {
#ifdef UNITY_ASSUME_UNIFORM_SCALING
    return UnityObjectToWorldDir(norm);
#else
    return normalize(mul(norm, (float3x3)unity_WorldToObject));
#endif
}

// ---------------------------------------------------------------------------------------------
// Light and view directions (not normalised). _WorldSpaceLightPos0 is (dir,0) or (pos,1).
// ---------------------------------------------------------------------------------------------
inline float3 UnityWorldSpaceLightDir(in float3 worldPos) {
    return _WorldSpaceLightPos0.xyz - worldPos * _WorldSpaceLightPos0.w;
}
inline float3 WorldSpaceLightDir(in float4 localPos) {
    return UnityWorldSpaceLightDir(mul(unity_ObjectToWorld, localPos).xyz);
}
// Object-space vector from the vertex towards the light (the direction for directional lights).
inline float3 ObjSpaceLightDir(in float4 v) {
    float3 objSpaceLightPos = mul(unity_WorldToObject, _WorldSpaceLightPos0).xyz;
    return objSpaceLightPos - v.xyz * _WorldSpaceLightPos0.w;
}
inline float3 UnityWorldSpaceViewDir(in float3 worldPos) { return _WorldSpaceCameraPos.xyz - worldPos; }
inline float3 WorldSpaceViewDir(in float4 localPos) {
    return UnityWorldSpaceViewDir(mul(unity_ObjectToWorld, localPos).xyz);
}
inline float3 ObjSpaceViewDir(in float4 v) {
    float3 objSpaceCameraPos = mul(unity_WorldToObject, float4(_WorldSpaceCameraPos.xyz, 1)).xyz;
    return objSpaceCameraPos - v.xyz;
}

// ---------------------------------------------------------------------------------------------
// Vertex lights. Formula: docs/LIGHTING.md §5 (Shade4PointLights, ShadeVertexLightsFull).
// ---------------------------------------------------------------------------------------------
// Diffuse from four point lights given as SoA world positions; atten = 1/(1 + d^2 * a) with
// a = unity_4LightAtten0 = 25/range^2; N.L clamped at 0; no range cut-off.
float3 Shade4PointLights(
    float4 lightPosX, float4 lightPosY, float4 lightPosZ,
    float3 lightColor0, float3 lightColor1, float3 lightColor2, float3 lightColor3,
    float4 lightAttenSq, float3 pos, float3 normal)
{
    float4 toLightX = lightPosX - pos.x;
    float4 toLightY = lightPosY - pos.y;
    float4 toLightZ = lightPosZ - pos.z;
    float4 lengthSq = toLightX * toLightX + toLightY * toLightY + toLightZ * toLightZ;
    lengthSq = max(lengthSq, 0.000001);
    float4 ndotl = toLightX * normal.x + toLightY * normal.y + toLightZ * normal.z;
    ndotl = max(float4(0, 0, 0, 0), ndotl * rsqrt(lengthSq));
    float4 atten = 1.0 / (1.0 + lengthSq * lightAttenSq);
    float4 diff = ndotl * atten;
    return lightColor0 * diff.x + lightColor1 * diff.y + lightColor2 * diff.z + lightColor3 * diff.w;
}

// Legacy Vertex-pass lighting in view space: ambient + sum of lightCount lights from the
// unity_LightPosition/Atten/SpotDirection/Color arrays (§5.1; spot factor per §5.1).
float3 ShadeVertexLightsFull(float4 vertex, float3 normal, int lightCount, bool spotLight) {
    float3 viewpos = UnityObjectToViewPos(vertex.xyz);
    float3 viewN = normalize(mul((float3x3)UNITY_MATRIX_IT_MV, normal));
    float3 lightColor = UNITY_LIGHTMODEL_AMBIENT.xyz;
    for (int i = 0; i < lightCount; i++) {
        float3 toLight = unity_LightPosition[i].xyz - viewpos.xyz * unity_LightPosition[i].w;
        float lengthSq = max(dot(toLight, toLight), 0.000001);
        toLight *= rsqrt(lengthSq);
        float atten = 1.0 / (1.0 + lengthSq * unity_LightAtten[i].z);
        if (spotLight) {
            float rho = max(0, dot(toLight, unity_SpotDirection[i].xyz));
            atten *= saturate((rho - unity_LightAtten[i].x) * unity_LightAtten[i].y);
        } else if (unity_LightPosition[i].w != 0 && lengthSq > unity_LightAtten[i].w) {
            atten = 0; // beyond the point light's range (w = range^2)
        }
        lightColor += unity_LightColor[i].rgb * (max(0, dot(viewN, toLight)) * atten);
    }
    return lightColor;
}
float3 ShadeVertexLights(float4 vertex, float3 normal) {
    return ShadeVertexLightsFull(vertex, normal, 4, false);
}

// ---------------------------------------------------------------------------------------------
// Spherical harmonics. Formula and packing: docs/LIGHTING.md §5, docs/SHADER_ABI.md §4.4. normal.w must be 1.
// ---------------------------------------------------------------------------------------------
half3 SHEvalLinearL0L1(half4 normal) {
    half3 x;
    x.r = dot(unity_SHAr, normal);
    x.g = dot(unity_SHAg, normal);
    x.b = dot(unity_SHAb, normal);
    return x;
}
// Light probe proxy volumes: varc has none (UNITY_LIGHT_PROBE_PROXY_VOLUME is 0, the
// runtime leaves unity_ProbeVolumeParams zero), so the volume's L0/L1 is the draw's own probe SH.
half3 SHEvalLinearL0L1_SampleProbeVolume(half4 normal, float3 worldPos) { return SHEvalLinearL0L1(normal); }
half3 SHEvalLinearL2(half4 normal) {
    half4 vB = normal.xyzz * normal.yzzx;   // (xy, yz, zz, zx)
    half3 x1;
    x1.r = dot(unity_SHBr, vB);
    x1.g = dot(unity_SHBg, vB);
    x1.b = dot(unity_SHBb, vB);
    half vC = normal.x * normal.x - normal.y * normal.y;
    return x1 + unity_SHC.rgb * vC;
}
half3 ShadeSH9(half4 normal) {
    half3 res = SHEvalLinearL0L1(normal) + SHEvalLinearL2(normal);
#ifdef UNITY_COLORSPACE_GAMMA
    res = LinearToGammaSpace(res);
#endif
    return res;
}
half3 ShadeSH12Order(half4 normal) {  // L0 + L1 only
    half3 res = SHEvalLinearL0L1(normal);
#ifdef UNITY_COLORSPACE_GAMMA
    res = LinearToGammaSpace(res);
#endif
    return res;
}
half3 ShadeSH3Order(half4 normal) {   // L2 only
    half3 res = SHEvalLinearL2(normal);
#ifdef UNITY_COLORSPACE_GAMMA
    res = LinearToGammaSpace(res);
#endif
    return res;
}

// 1 when the pass samples light-probe SH (LIGHTPROBE_SH outside add/prepass/caster/meta passes).
#if defined(LIGHTPROBE_SH) && !defined(UNITY_PASS_FORWARDADD) && !defined(UNITY_PASS_PREPASSBASE) && !defined(UNITY_PASS_SHADOWCASTER) && !defined(UNITY_PASS_META)
#define UNITY_SHOULD_SAMPLE_SH 1
#else
#define UNITY_SHOULD_SAMPLE_SH 0
#endif

// ---------------------------------------------------------------------------------------------
// Texture coordinates, screen positions, depth.
// ---------------------------------------------------------------------------------------------
#define TRANSFORM_TEX(tex, name) (tex.xy * name##_ST.xy + name##_ST.zw)

// Homogeneous screen coordinates: xy / w in [0,1], (0,0) = first row/column of render targets.
inline float4 ComputeNonStereoScreenPos(float4 pos) {
    float4 o = pos * 0.5f;
    o.xy = float2(o.x, o.y * _ProjectionParams.x) + o.w;
    o.zw = pos.zw;
    return o;
}
inline float4 ComputeScreenPos(float4 pos) { return ComputeNonStereoScreenPos(pos); }
inline float4 ComputeGrabScreenPos(float4 pos) {
    float4 o = pos * 0.5f;
    o.xy = float2(o.x, o.y) + o.w;   // grab textures share the framebuffer's row order
    o.zw = pos.zw;
    return o;
}

// Raw depth z in [0,1] -> linear depth: Linear01Depth = eye depth / far, LinearEyeDepth in units.
inline float Linear01Depth(float z) { return 1.0 / (_ZBufferParams.x * z + _ZBufferParams.y); }
inline float LinearEyeDepth(float z) { return 1.0 / (_ZBufferParams.z * z + _ZBufferParams.w); }
#define COMPUTE_EYEDEPTH(o) o = -UnityObjectToViewPos(v.vertex).z
#define COMPUTE_DEPTH_01 -(UnityObjectToViewPos(v.vertex).z * _ProjectionParams.w)
#define COMPUTE_VIEW_NORMAL normalize(mul((float3x3)UNITY_MATRIX_IT_MV, v.normal))

// ---------------------------------------------------------------------------------------------
// Packing helpers.
// ---------------------------------------------------------------------------------------------
inline float4 EncodeFloatRGBA(float v) {
    float4 enc = float4(1.0, 255.0, 65025.0, 16581375.0) * v;
    enc = frac(enc);
    enc -= enc.yzww * float4(1.0 / 255.0, 1.0 / 255.0, 1.0 / 255.0, 0.0);
    return enc;
}
inline float DecodeFloatRGBA(float4 enc) {
    return dot(enc, float4(1.0, 1 / 255.0, 1 / 65025.0, 1 / 16581375.0));
}
inline float2 EncodeFloatRG(float v) {
    float2 enc = float2(1.0, 255.0) * v;
    enc = frac(enc);
    enc.x -= enc.y * (1.0 / 255.0);
    return enc;
}
inline float DecodeFloatRG(float2 enc) { return dot(enc, float2(1.0, 1 / 255.0)); }

// Normal maps are plain RGB (UNITY_NO_DXT5nm): n = rgb * 2 - 1.
inline fixed3 UnpackNormalDXT5nm(fixed4 packednormal) {
    fixed3 normal;
    normal.xy = packednormal.wy * 2 - 1;
    normal.z = sqrt(1 - saturate(dot(normal.xy, normal.xy)));
    return normal;
}
inline fixed3 UnpackNormal(fixed4 packednormal) { return packednormal.xyz * 2 - 1; }

// The legacy distance cube encoding (kept for shaders that call it; varc's point-light shadow
// maps are depth cube maps).
inline float4 UnityEncodeCubeShadowDepth(float z) { return float4(z, z, z, z); }
inline float UnityDecodeCubeShadowDepth(float4 vals) { return vals.r; }

// ---------------------------------------------------------------------------------------------
// Shadow casters. Every map is a depth map, as on Vulkan in Unity (SHADOWS_CUBE_IN_DEPTH_TEX):
// spot and directional lights (SHADOWS_DEPTH) and each face of a point light's depth cube map
// (SHADOWS_CUBE) store the caster's depth after a normal offset and a linear bias in clip space
// (docs/LIGHTING.md §6); point lights get no linear bias here (unity_LightShadowBias.x = 0), their
// receivers subtract it (_LightProjectionParams.z).
// ---------------------------------------------------------------------------------------------
float4 UnityClipSpaceShadowCasterPos(float4 vertex, float3 normal) {
    float4 wPos = mul(unity_ObjectToWorld, vertex);
    if (unity_LightShadowBias.z != 0.0) {
        float3 wNormal = UnityObjectToWorldNormal(normal);
        float3 wLight = normalize(UnityWorldSpaceLightDir(wPos.xyz));
        float shadowCos = dot(wNormal, wLight);
        float shadowSine = sqrt(1 - shadowCos * shadowCos);
        float normalBias = unity_LightShadowBias.z * shadowSine;
        wPos.xyz -= wNormal * normalBias;
    }
    return mul(UNITY_MATRIX_VP, wPos);
}
float4 UnityApplyLinearShadowBias(float4 clipPos) {
    clipPos.z += saturate(unity_LightShadowBias.x / clipPos.w) * clipPos.w;
    clipPos.z = min(clipPos.z, clipPos.w);
    return clipPos;
}
#define V2F_SHADOW_CASTER_NOPOS
#define TRANSFER_SHADOW_CASTER_NOPOS(o, opos) \
    opos = UnityApplyLinearShadowBias(UnityClipSpaceShadowCasterPos(v.vertex, v.normal));
#define SHADOW_CASTER_FRAGMENT(i) return 0;
#define V2F_SHADOW_CASTER V2F_SHADOW_CASTER_NOPOS float4 pos : SV_POSITION
#define TRANSFER_SHADOW_CASTER(o) TRANSFER_SHADOW_CASTER_NOPOS(o, o.pos)
#define TRANSFER_SHADOW_CASTER_NORMALOFFSET(o) TRANSFER_SHADOW_CASTER_NOPOS(o, o.pos)
// Unity's pre-normal-offset spelling: the same caster position here (the bias is applied alike).
#define TRANSFER_SHADOW_CASTER_NOPOS_LEGACY(o, opos) TRANSFER_SHADOW_CASTER_NOPOS(o, opos)

// ---------------------------------------------------------------------------------------------
// Fog (docs/LIGHTING.md §7). The fog coordinate is the eye depth (clip w) in world units.
// ---------------------------------------------------------------------------------------------
#if defined(UNITY_PASS_PREPASSBASE) || defined(UNITY_PASS_DEFERRED) || defined(UNITY_PASS_SHADOWCASTER)
    #undef FOG_LINEAR
    #undef FOG_EXP
    #undef FOG_EXP2
#endif
#if defined(FOG_LINEAR)
    #define UNITY_CALC_FOG_FACTOR_RAW(coord) float unityFogFactor = (coord) * unity_FogParams.z + unity_FogParams.w
#elif defined(FOG_EXP)
    #define UNITY_CALC_FOG_FACTOR_RAW(coord) float unityFogFactor = exp2(-unity_FogParams.y * (coord))
#elif defined(FOG_EXP2)
    #define UNITY_CALC_FOG_FACTOR_RAW(coord) float unityFogFactor = unity_FogParams.x * (coord); unityFogFactor = exp2(-unityFogFactor * unityFogFactor)
#else
    #define UNITY_CALC_FOG_FACTOR_RAW(coord) float unityFogFactor = 0.0
#endif
#define UNITY_CALC_FOG_FACTOR(coord) UNITY_CALC_FOG_FACTOR_RAW(coord)
// The blend towards the fog colour exists in every variant, as in Unity (shaders call it with
// their own factor).
#define UNITY_FOG_LERP_COLOR(col, fogCol, fogFac) col.rgb = lerp((fogCol).rgb, (col).rgb, saturate(fogFac))
// The packed form declares its member in every variant: shaders keep other data in the vector's
// other components (the Standard shader's simple path keeps its reflection vector in yzw).
#define UNITY_FOG_COORDS_PACKED(idx, vectype) vectype fogCoord : TEXCOORD##idx;
#if defined(FOG_LINEAR) || defined(FOG_EXP) || defined(FOG_EXP2)
    #define UNITY_FOG_COORDS(idx) UNITY_FOG_COORDS_PACKED(idx, float1)
    // Generated surface code reads the fog coordinate into a local, then UNITY_APPLY_FOG(s it.
    #define UNITY_EXTRACT_FOG(name) float _unity_fogCoord = name.fogCoord
    // glslang treats float1 as a scalar, whose .x is not assignable: assign the whole member.
    #define UNITY_TRANSFER_FOG(o, outpos) o.fogCoord = (outpos).w
    #define UNITY_APPLY_FOG_COLOR(coord, col, fogCol) { UNITY_CALC_FOG_FACTOR((coord).x); UNITY_FOG_LERP_COLOR(col, fogCol, unityFogFactor); }
#else
    #define UNITY_FOG_COORDS(idx)
    #define UNITY_EXTRACT_FOG(name)
    #define UNITY_TRANSFER_FOG(o, outpos)
    #define UNITY_APPLY_FOG_COLOR(coord, col, fogCol)
#endif
#ifdef UNITY_PASS_FORWARDADD
    #define UNITY_APPLY_FOG(coord, col) UNITY_APPLY_FOG_COLOR(coord, col, fixed4(0, 0, 0, 0))
#else
    #define UNITY_APPLY_FOG(coord, col) UNITY_APPLY_FOG_COLOR(coord, col, unity_FogColor)
#endif

// ---------------------------------------------------------------------------------------------
// Image-effect vertex program.
// ---------------------------------------------------------------------------------------------
struct v2f_img {
    float4 pos : SV_POSITION;
    half2 uv : TEXCOORD0;
    UNITY_VERTEX_INPUT_INSTANCE_ID
    UNITY_VERTEX_OUTPUT_STEREO
};
v2f_img vert_img(appdata_img v) {
    v2f_img o;
    UNITY_SETUP_INSTANCE_ID(v);
    UNITY_TRANSFER_INSTANCE_ID(v, o);
    o.pos = UnityObjectToClipPos(v.vertex);
    o.uv = v.texcoord;
    return o;
}

// The legacy vertex-lit interpolants and their combine: texture * per-vertex diffuse plus
// per-vertex specular masked by the texture's alpha (gloss); alpha = texture * diffuse alpha.
struct v2f_vertex_lit {
    float2 uv : TEXCOORD0;
    fixed4 diff : COLOR0;
    fixed4 spec : COLOR1;
};
inline fixed4 VertexLight(v2f_vertex_lit i, sampler2D mainTex) {
    fixed4 texel = tex2D(mainTex, i.uv);
    return fixed4(texel.rgb * i.diff.rgb + i.spec.rgb * texel.a, texel.a * i.diff.a);
}

// =============================================================================================
// Additions for third-party shaders. Everything below only adds names; nothing above uses it.
// =============================================================================================

// Light-type helpers of the forward passes: set when the variant renders a directional light.
#if defined(POINT) || defined(SPOT) || defined(DIRECTIONAL) || defined(POINT_COOKIE) || defined(DIRECTIONAL_COOKIE)
#define USING_LIGHT_MULTI_COMPILE
#endif
// USING_DIRECTIONAL_LIGHT: UnityShaderVariables.cginc.

// Unity 4's texture-matrix transform of the vertex input `v`'s first uv (identity matrices).
#define TRANSFORM_UV(idx) mul(UNITY_MATRIX_TEXTURE##idx, v.texcoord).xy

// Alpha of opaque passes: forced to 1 (the framebuffer alpha stays meaningful).
#define UNITY_OPAQUE_ALPHA(outputAlpha) outputAlpha = 1.0

// A view-space vector (e.g. an extruded normal) projected to clip space without translation:
// the upper-left 2x2 / 3x3 of UNITY_MATRIX_P. Used for screen-constant outline widths.
inline float2 TransformViewToProjection(float2 v) { return mul((float2x2)UNITY_MATRIX_P, v); }
inline float3 TransformViewToProjection(float3 v) { return mul((float3x3)UNITY_MATRIX_P, v); }

// Pixel snapping for 2D sprites: round the clip position to the pixel grid of _ScreenParams.
inline float4 UnityPixelSnap(float4 pos) {
    float2 hpc = _ScreenParams.xy * 0.5f;
    float2 pixelPos = round((pos.xy / pos.w) * hpc);
    pos.xy = pixelPos / hpc * pos.w;
    return pos;
}

// ---------------------------------------------------------------------------------------------
// View-space normals packed in two channels by stereographic projection (the format of Unity's
// _CameraDepthNormalsTexture: xy = normal, zw = EncodeFloatRG(Linear01Depth)).
// Encode: p = n.xy / (n.z + 1) / K * 0.5 + 0.5 with K = 1.7777 (covers normals facing up to
// ~2.3 rad from the viewer). Decode inverts the projection.
// ---------------------------------------------------------------------------------------------
#define VARC_STEREO_NORMAL_SCALE 1.7777
inline float2 EncodeViewNormalStereo(float3 n) {
    float2 p = n.xy / (n.z + 1.0);
    p /= VARC_STEREO_NORMAL_SCALE;
    return p * 0.5 + 0.5;
}
inline float3 DecodeViewNormalStereo(float4 enc4) {
    float3 q = float3(enc4.xy * (2.0 * VARC_STEREO_NORMAL_SCALE) - VARC_STEREO_NORMAL_SCALE, 1.0);
    float g = 2.0 / dot(q, q);
    return float3(g * q.xy, g - 1.0);
}
inline float4 EncodeDepthNormal(float depth, float3 normal) {
    return float4(EncodeViewNormalStereo(normal), EncodeFloatRG(depth));
}
inline void DecodeDepthNormal(float4 enc, out float depth, out float3 normal) {
    depth = DecodeFloatRG(enc.zw);
    normal = DecodeViewNormalStereo(enc);
}

// ---------------------------------------------------------------------------------------------
// HDR-encoded textures (reflection probes). decodeInstructions = (scale, exponent, -, useAlpha):
// rgb * scale * a^exponent when useAlpha = 1 (RGBM-style), rgb * scale when useAlpha = 0.
// varc's runtime binds float cubes with (1, 1, 0, 0), which decodes to rgb (SHADER_ABI.md §6).
// ---------------------------------------------------------------------------------------------
inline half3 DecodeHDR(half4 data, half4 decodeInstructions) {
    half alpha = decodeInstructions.w * (data.a - 1.0) + 1.0;   // w = 1: alpha is used
    return (decodeInstructions.x * pow(abs(alpha), decodeInstructions.y)) * data.rgb;
}

// ---------------------------------------------------------------------------------------------
// Lightmaps (declared in UnityShaderVariables.cginc; SHADER_ABI.md §4.13). varc's lightmaps are
// linear HDR colour (UNITY_LIGHTMAP_FULL_HDR): decoding is the identity on rgb.
// ---------------------------------------------------------------------------------------------
#define UNITY_LIGHTMAP_FULL_HDR 1
inline half3 DecodeLightmap(fixed4 color) { return color.rgb; }
inline half3 DecodeLightmap(fixed4 color, half4 decodeInstructions) { return color.rgb; }
inline half3 DecodeRealtimeLightmap(fixed4 color) { return color.rgb; }
// Directional lightmaps: dirTex.xyz = dominant direction * 0.5 + 0.5, w = its rebalancing factor;
// the half-Lambert term against the normal scales the colour.
inline half3 DecodeDirectionalLightmap(half3 color, fixed4 dirTex, half3 normalWorld) {
    half halfLambert = dot(normalWorld, dirTex.xyz - 0.5) + 0.5;
    return color * halfLambert / max(1e-4h, dirTex.w);
}

// ---------------------------------------------------------------------------------------------
// Stereo rendering. varc renders one eye per pass (no UNITY_SINGLE_PASS_STEREO, no stereo
// instancing): every screen-space adjustment is the identity and unity_StereoEyeIndex is 0.
// ---------------------------------------------------------------------------------------------
inline float2 UnityStereoScreenSpaceUVAdjust(float2 uv, float4 scaleAndOffset) { return uv; }
inline float4 UnityStereoScreenSpaceUVAdjust(float4 uv, float4 scaleAndOffset) { return uv; }
inline float2 UnityStereoTransformScreenSpaceTex(float2 uv) { return uv; }
inline float4 UnityStereoTransformScreenSpaceTex(float4 uv) { return uv; }
inline float2 UnityStereoClamp(float2 uv) { return uv; }
inline float2 UnityStereoClamp(float2 uv, float4 scaleAndOffset) { return uv; }
// The adjustment itself, which Unity applies only in single-pass stereo: uv * scale + offset
// (for a float4, to both halves).
inline float2 UnityStereoScreenSpaceUVAdjustInternal(float2 uv, float4 scaleAndOffset) {
    return uv * scaleAndOffset.xy + scaleAndOffset.zw;
}
inline float4 UnityStereoScreenSpaceUVAdjustInternal(float4 uv, float4 scaleAndOffset) {
    return float4(UnityStereoScreenSpaceUVAdjustInternal(uv.xy, scaleAndOffset),
                  UnityStereoScreenSpaceUVAdjustInternal(uv.zw, scaleAndOffset));
}
#define UnityStereoClampScaleOffset(uv, scaleAndOffset) (uv)
#define TRANSFORM_TEX_STEREO(tex, name) TRANSFORM_TEX(tex, name)
#define UNITY_DECLARE_SCREENSPACE_SHADOWMAP_STEREO(tex) UNITY_DECLARE_SCREENSPACE_SHADOWMAP(tex)

// ---------------------------------------------------------------------------------------------
// LOD cross-fade (LOD_FADE_CROSSFADE): the two LOD levels in transition share the screen through
// a 4x4 ordered dither at the pixel position |vpos|. unity_LODFade.x = f in (0, 1] keeps that
// share of each 4x4 tile; -f keeps exactly the other pixels (the level fading out).
// ---------------------------------------------------------------------------------------------
#ifdef LOD_FADE_CROSSFADE
// Thresholds of the 4x4 Bayer matrix, (rank + 0.5) / 16, row by row.
static const float kUnityCrossFadeDither[16] = {
    0.03125, 0.53125, 0.15625, 0.65625, 0.78125, 0.28125, 0.90625, 0.40625,
    0.21875, 0.71875, 0.09375, 0.59375, 0.96875, 0.46875, 0.84375, 0.34375};
void UnityApplyDitherCrossFade(float2 vpos) {
    uint2 cell = uint2(vpos) & 3u;
    float threshold = kUnityCrossFadeDither[cell.y * 4u + cell.x];
    float fade = unity_LODFade.x;
    clip(fade >= 0 ? fade - threshold : threshold + fade);
}
#define UNITY_APPLY_DITHER_CROSSFADE(vpos) UnityApplyDitherCrossFade((vpos).xy)
// Unity 5.6's pair: the projective screen position (x, y, w) from the vertex stage, and the
// same dither at the pixel it projects to (no dither-mask texture here: the Bayer matrix above).
half3 ComputeDitherScreenPos(float4 hPos) { return ComputeScreenPos(hPos).xyw; }
void ApplyDitherCrossFade(half3 ditherScreenPos) {
    UnityApplyDitherCrossFade(ditherScreenPos.xy / ditherScreenPos.z * _ScreenParams.xy);
}
#else
#define UNITY_APPLY_DITHER_CROSSFADE(vpos)
#endif

// ---------------------------------------------------------------------------------------------
// Helpers added for third-party shaders (issue #27, docs/BUILTIN_API.md).
// ---------------------------------------------------------------------------------------------
// True when the project renders in gamma colour space (UNITY_COLORSPACE_GAMMA); varc renders in
// linear space, so false unless a shader defines that macro itself.
inline bool IsGammaSpace() {
#ifdef UNITY_COLORSPACE_GAMMA
    return true;
#else
    return false;
#endif
}

// Parallax mapping: the uv offset for a height sample h in [0, 1] of a map scaled by |height|,
// seen along the tangent-space view direction viewDir. The height is centred on 0
// (h * height - height / 2) and moved along the view's xy, divided by its z biased by 0.42 so
// that grazing views stay bounded.
inline float2 ParallaxOffset(half h, half height, half3 viewDir) {
    float centred = h * height - height * 0.5;
    float3 v = normalize(viewDir);
    return centred * (v.xy / (v.z + 0.42));
}

// Terrain heightmaps. Vulkan does not guarantee sampling 16-bit unorm textures, so (as Unity
// does where R16 is not guaranteed) a height h in [0, 1] is stored in two 8-bit channels:
// r = the low byte, g = the high byte of round(h * 65535).
#define API_HAS_GUARANTEED_R16_SUPPORT 0
inline float UnpackHeightmap(float4 height) { return (height.r + height.g * 256.0) / 257.0; }
inline float4 PackHeightmap(float height) {
    float value = round(saturate(height) * 65535.0);
    float high = floor(value / 256.0);
    return float4((value - high * 256.0) / 255.0, high / 255.0, 0, 0);
}

// A normal-map texel (plain RGB, UNITY_NO_DXT5nm) to a tangent-space normal whose xy (the bump)
// is scaled by |scale|; not renormalised.
inline fixed3 UnpackNormalWithScale(fixed4 packednormal, float scale) {
    fixed3 normal = packednormal.xyz * 2 - 1;
    normal.xy *= scale;
    return normal;
}

// The caster position of a float3 object-space vertex (w = 1).
float4 UnityClipSpaceShadowCasterPos(float3 vertex, float3 normal) {
    return UnityClipSpaceShadowCasterPos(float4(vertex, 1.0), normal);
}

// Clip-space z to a distance that is 0 at the near plane and grows towards the far plane (the fog
// coordinate): Vulkan clip z is already 0 at near and not reversed (SHADER_ABI.md §2).
#define UNITY_Z_0_FAR_FROM_CLIPSPACE(coord) max((coord), 0)

// Single-pass stereo is not supported (see above): the eye's screen-space uv is the uv itself.
#define TransformStereoScreenSpaceTex(uv, w) (uv)

// HDR texture decoding with the colour space given (colorspaceIsGamma: alpha^y is skipped, the
// gamma-space encoding multiplies by alpha directly).
inline half3 DecodeHDR(half4 data, half4 decodeInstructions, int colorspaceIsGamma) {
    half alpha = decodeInstructions.w * (data.a - 1.0) + 1.0;
    if (colorspaceIsGamma)
        return (decodeInstructions.x * alpha) * data.rgb;
    return (decodeInstructions.x * pow(abs(alpha), decodeInstructions.y)) * data.rgb;
}

// Other lightmap encodings (varc's runtime binds full-HDR lightmaps, SHADER_ABI.md; these decode
// textures a shader holds itself). RGBM: rgb * x * a^y. Double LDR: rgb in [0, 2] stored halved,
// times x (2 in gamma space, 2^2.2 = unity_ColorSpaceDouble in linear space).
inline half3 DecodeLightmapRGBM(half4 data, half4 decodeInstructions) {
    return (decodeInstructions.x * pow(abs(data.a), decodeInstructions.y)) * data.rgb;
}
inline half3 DecodeLightmapDoubleLDR(fixed4 color, half4 decodeInstructions) {
    return decodeInstructions.x * color.rgb;
}
inline half3 DecodeLightmapDoubleLDR(fixed4 color) {
    return unity_ColorSpaceDouble.rgb * color.rgb;
}
#define LIGHTMAP_RGBM_SCALE 5.0
#define EMISSIVE_RGBM_SCALE 97.0

// RGBM encoding of an HDR colour up to maxRGBM: rgb / maxRGBM divided by a multiplier a (the
// largest channel, at least 1e-6, rounded up to 1/255) stored in alpha; rgb = data.rgb * a * maxRGBM.
inline half4 UnityEncodeRGBM(half3 color, float maxRGBM) {
    float3 scaled = color * (1.0 / maxRGBM);
    float alpha = max(max(scaled.r, scaled.g), max(scaled.b, 1e-6));
    alpha = ceil(alpha * 255.0) / 255.0;
    return half4(scaled / alpha, alpha);
}

// Two-channel normal maps: x in the red channel or (BC5/DXT5nm) in alpha (x = r * a covers both
// when the unused one is 1), y in green, z reconstructed for a unit vector.
inline fixed3 UnpackNormalmapRGorAG(fixed4 packednormal) {
    packednormal.x *= packednormal.w;
    fixed3 normal;
    normal.xy = packednormal.xy * 2 - 1;
    normal.z = sqrt(1 - saturate(dot(normal.xy, normal.xy)));
    return normal;
}

// The uv transformed by a matrix (a texture matrix): mul(mat, (uv, 0, 0)).xy.
inline float2 MultiplyUV(float4x4 mat, float2 inUV) {
    return mul(mat, float4(inUV, 0, 0)).xy;
}

// Depth-texture helpers of shaders that render depth themselves. Vulkan has native depth
// textures, so, as on every such platform, there is nothing to transfer and the colour output is
// 0 (Unity manual, "Depth textures").
#define UNITY_TRANSFER_DEPTH(oo)
#define UNITY_OUTPUT_DEPTH(i) return 0
#define DECODE_EYEDEPTH(i) LinearEyeDepth(i)
#define V2F_SCREEN_TYPE float4
#define UNITY_HALF_MIN 6.103515625e-5

// LOD cross-fade reads the pixel position (UNITY_APPLY_DITHER_CROSSFADE(vpos)); the older macros
// that passed a dither coordinate through the interpolators declare and transfer nothing.
#define UNITY_DITHER_CROSSFADE_COORDS
#define UNITY_DITHER_CROSSFADE_COORDS_IDX(idx)
#define UNITY_TRANSFER_DITHER_CROSSFADE(o, v)
#define UNITY_TRANSFER_DITHER_CROSSFADE_HPOS(o, hpos)

// Set when V2F_SHADOW_CASTER_NOPOS declares nothing: always, with depth cube maps.
#define V2F_SHADOW_CASTER_NOPOS_IS_EMPTY
#define SHADOWS_CUBE_IN_DEPTH_TEX

// Dither-mask textures of LOD cross-fade (Unity 2019.4+ and the older name): declared for
// programs that sample them; varc's own cross-fade uses the Bayer matrix above.
#ifdef LOD_FADE_CROSSFADE
sampler2D unity_DitherMask;
sampler2D _DitherMaskLOD2D;
#endif

#include "VarcFogTbnPacking.cginc"
#include "VarcShadowCollector.cginc"

#endif // UNITY_CG_INCLUDED
