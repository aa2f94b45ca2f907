Shader "FuzzBuild/Keywords" {
    Properties { _Color ("Color", Color) = (1,1,1,1) _MainTex ("Tex", 2D) = "white" {} }
    SubShader {
        Tags { "RenderType"="Opaque" }
        Pass {
            Tags { "LightMode"="ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile _ TINT
            #pragma shader_feature_local_fragment _ INVERT
            #include "UnityCG.cginc"
            #include "f1.h"
            sampler2D _MainTex;
            float4 _MainTex_ST;
            struct v2f { float4 pos : SV_POSITION; float2 uv : TEXCOORD0; };
            v2f vert(appdata_base v) {
                v2f o;
                o.pos = UnityObjectToClipPos(v.vertex);
                o.uv = TRANSFORM_TEX(v.texcoord, _MainTex);
                return o;
            }
            float4 frag(v2f i) : SV_Target {
                float4 c = tex2D(_MainTex, i.uv);
            #ifdef TINT
                c = tint(c);
            #endif
            #ifdef INVERT
                c.rgb = 1 - c.rgb;
            #endif
                return c;
            }
            ENDCG
        }
    }
}
//@@file
#ifndef F1_H
#define F1_H
float4 _Color;
float4 tint(float4 c) { return c * _Color; }
#endif
