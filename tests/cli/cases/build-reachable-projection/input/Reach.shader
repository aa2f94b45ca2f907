// A forward-base pass whose fragment stage calls no lighting function of UnityCG: the lighting
// keywords Unity's includes test only in code it never reaches, and DETAIL only in a function
// nothing calls, do not multiply its preprocessing.
Shader "Test/Reach" {
    SubShader {
        Pass {
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile_fwdbase
            #pragma multi_compile _ DETAIL
            #pragma multi_compile _ TINT
            #include "UnityCG.cginc"
            fixed4 _Color;
            float4 vert(float4 v : POSITION) : SV_POSITION { return UnityObjectToClipPos(v); }
            float unusedDetail(float x) {
            #ifdef DETAIL
                x *= 2;
            #endif
                return x;
            }
            fixed4 frag() : SV_Target {
                fixed4 c = _Color;
            #ifdef TINT
                c.rgb *= 0.5;
            #endif
                return c;
            }
            ENDCG
        }
    }
}
