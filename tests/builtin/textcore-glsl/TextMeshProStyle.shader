// SPDX-License-Identifier: Apache-2.0
// A distance-field text shader with its own programs, in the shape of TextMeshPro's mobile SDF
// shaders: the TextCore properties under both file names (2021.3 and 2022.3), a per-vertex scale
// from uv1 and the screen, outline / underlay / glow keywords and the UI clipping keywords.
// builtin.textcore-glsl builds every variant. Written for varc's tests.
Shader "varc-tests/TextMeshProStyle" {
    Properties {
        _FaceColor ("Face colour", Color) = (1, 1, 1, 1)
        _OutlineColor ("Outline colour", Color) = (0, 0, 0, 1)
        _OutlineWidth ("Outline thickness", Range(0, 1)) = 0
        _MainTex ("Font atlas", 2D) = "white" {}
        _GradientScale ("Gradient scale", Float) = 5
        _ClipRect ("Clip rect", Vector) = (-32767, -32767, 32767, 32767)
    }
    SubShader {
        Tags { "Queue" = "Transparent" "RenderType" = "Transparent" }
        Cull Off ZWrite Off
        Blend One OneMinusSrcAlpha
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile __ OUTLINE_ON
            #pragma multi_compile __ UNDERLAY_ON UNDERLAY_INNER
            #pragma multi_compile __ GLOW_ON
            #pragma multi_compile __ UNITY_UI_CLIP_RECT
            #pragma multi_compile __ UNITY_UI_ALPHACLIP
            #include "UnityCG.cginc"
            #include "UnityUI.cginc"
            #include "TextCore_Properties.cginc"
            #include "TextCoreProperties.cginc"

            struct appdata {
                float4 vertex : POSITION;
                float4 color : COLOR;
                float2 uv0 : TEXCOORD0;
                float2 uv1 : TEXCOORD1;
            };
            struct v2f {
                float4 pos : SV_POSITION;
                fixed4 color : COLOR;
                float4 uv : TEXCOORD0;     // xy atlas uv, z scale, w bias
                float2 mask : TEXCOORD1;
            };

            v2f vert(appdata v) {
                v2f o;
                float4 vert = v.vertex + float4(_VertexOffsetX, _VertexOffsetY, 0, 0);
                o.pos = UnityObjectToClipPos(vert);
                float2 pixelSize = o.pos.w / (float2(_ScaleX, _ScaleY) * abs(mul((float2x2)UNITY_MATRIX_P, _ScreenParams.xy)) + 1e-5);
                float scale = rsqrt(dot(pixelSize, pixelSize)) * abs(v.uv1.y) * _GradientScale * (_Sharpness + 1);
                float weight = lerp(_WeightNormal, _WeightBold, step(v.uv1.y, 0)) / 4.0;
                float bias = (0.5 - (weight + _FaceDilate) * _ScaleRatioA * 0.5) * scale - 0.5;
                o.uv = float4(v.uv0, scale, bias);
                o.color = v.color * _FaceColor;
                o.mask = vert.xy;
                return o;
            }

            fixed4 frag(v2f i) : SV_Target {
                float d = tex2D(_MainTex, i.uv.xy).a * i.uv.z;
                fixed4 c = i.color * saturate(d - i.uv.w);
            #if defined(OUTLINE_ON)
                c = lerp(_OutlineColor * i.color.a, c, saturate(d - i.uv.w - _OutlineWidth * _ScaleRatioA * i.uv.z));
            #endif
            #if defined(UNDERLAY_ON) || defined(UNDERLAY_INNER)
                float u = tex2D(_MainTex, i.uv.xy - float2(_UnderlayOffsetX, _UnderlayOffsetY) * _ScaleRatioC / _TextureWidth).a;
                c += _UnderlayColor * saturate(u * i.uv.z - i.uv.w + _UnderlayDilate) * (1 - c.a);
            #endif
            #if defined(GLOW_ON)
                c.rgb += _GlowColor.rgb * _GlowColor.a * saturate(1 - abs(d - i.uv.w) / max(_GlowOuter * i.uv.z, 1e-4));
            #endif
            #if defined(UNITY_UI_CLIP_RECT)
                c *= UnityGet2DClipping(i.mask, _ClipRect);
            #endif
            #if defined(UNITY_UI_ALPHACLIP)
                clip(c.a - 0.001);
            #endif
                return c;
            }
            ENDCG
        }
    }
}
