// A ForwardBase pass with one shader_feature: _DETAIL draws red, without it the material colour.
Shader "Custom/Detail" {
    Properties { _Color ("Color", Color) = (0.25, 0.5, 1, 1) }
    SubShader {
        Pass {
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma shader_feature _ _DETAIL
            #include "UnityCG.cginc"
            float4 _Color;
            float4 vert(float4 position : POSITION) : SV_POSITION {
                return UnityObjectToClipPos(position);
            }
            float4 frag() : SV_Target {
            #ifdef _DETAIL
                return float4(1, 0, 0, 1);
            #else
                return _Color;
            #endif
            }
            ENDCG
        }
    }
}
