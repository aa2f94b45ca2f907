// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnitySprites.cginc. Vertex and fragment programs of Unity's default sprite
// shader: the sprite renderer's colour and flip, optional pixel snapping (PIXELSNAP_ON), an
// external alpha texture (ETC1_EXTERNAL_ALPHA) and premultiplied-alpha output. Written for varc
// from the documented behaviour; not derived from Unity.
#ifndef UNITY_SPRITES_INCLUDED
#define UNITY_SPRITES_INCLUDED

#include "UnityCG.cginc"

// Per-renderer values: the SpriteRenderer's colour and flip (x, y: 1 or -1), one element per
// instance when instanced.
#ifdef UNITY_INSTANCING_ENABLED
    UNITY_INSTANCING_BUFFER_START(PerDrawSprite)
        UNITY_DEFINE_INSTANCED_PROP(fixed4, unity_SpriteRendererColorArray)
        UNITY_DEFINE_INSTANCED_PROP(fixed2, unity_SpriteFlipArray)
    UNITY_INSTANCING_BUFFER_END(PerDrawSprite)
    #define _RendererColor UNITY_ACCESS_INSTANCED_PROP(PerDrawSprite, unity_SpriteRendererColorArray)
    #define _Flip UNITY_ACCESS_INSTANCED_PROP(PerDrawSprite, unity_SpriteFlipArray)
#else
CBUFFER_START(UnityPerDrawSprite)
    fixed4 _RendererColor;
    fixed2 _Flip;
CBUFFER_END
#endif

// Material values.
fixed4 _Color;
sampler2D _MainTex;
sampler2D _AlphaTex;           // ETC1_EXTERNAL_ALPHA: alpha in .r
float _EnableExternalAlpha;

struct appdata_t {
    float4 vertex : POSITION;
    float4 color : COLOR;
    float2 texcoord : TEXCOORD0;
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

struct v2f {
    float4 vertex : SV_POSITION;
    fixed4 color : COLOR;
    float2 texcoord : TEXCOORD0;
    UNITY_VERTEX_OUTPUT_STEREO
};

// The object-space position with x and y multiplied by flip (w = 1).
inline float4 UnityFlipSprite(in float3 pos, in fixed2 flip) {
    return float4(pos.xy * flip, pos.z, 1.0);
}

// Clip position of the flipped vertex (snapped to pixels with PIXELSNAP_ON); colour = vertex
// colour * _Color * _RendererColor.
v2f SpriteVert(appdata_t IN) {
    v2f OUT;
    UNITY_SETUP_INSTANCE_ID(IN);
    UNITY_INITIALIZE_OUTPUT(v2f, OUT);
    OUT.vertex = UnityFlipSprite(IN.vertex.xyz, _Flip);
    OUT.vertex = UnityObjectToClipPos(OUT.vertex);
    OUT.texcoord = IN.texcoord;
    OUT.color = IN.color * _Color * _RendererColor;
#ifdef PIXELSNAP_ON
    OUT.vertex = UnityPixelSnap(OUT.vertex);
#endif
    return OUT;
}

// _MainTex at uv; with ETC1_EXTERNAL_ALPHA the alpha comes from _AlphaTex.r where
// _EnableExternalAlpha is 1.
fixed4 SampleSpriteTexture(float2 uv) {
    fixed4 color = tex2D(_MainTex, uv);
#if ETC1_EXTERNAL_ALPHA
    fixed4 alpha = tex2D(_AlphaTex, uv);
    color.a = lerp(color.a, alpha.r, _EnableExternalAlpha);
#endif
    return color;
}

// Texture times vertex colour, rgb premultiplied by alpha (the sprite shaders blend One
// OneMinusSrcAlpha).
fixed4 SpriteFrag(v2f IN) : SV_Target {
    fixed4 c = SampleSpriteTexture(IN.texcoord) * IN.color;
    c.rgb *= c.a;
    return c;
}

#endif // UNITY_SPRITES_INCLUDED
