Shader "Fuzz/Unlit" {
    SubShader { Pass {
        CGPROGRAM
        #pragma vertex vert
        #pragma fragment frag
        #pragma multi_compile _ TINT
        #include "UnityCG.cginc"
        float4 _Color;
        struct v2f { float4 pos : SV_POSITION; float2 uv : TEXCOORD0; };
        v2f vert(appdata_base v) { v2f o; o.pos = UnityObjectToClipPos(v.vertex); o.uv = v.texcoord.xy; return o; }
        float4 frag(v2f i) : SV_Target {
        #ifdef TINT
            return _Color * float4(i.uv, 0, 1);
        #else
            return float4(i.uv, 0, 1);
        #endif
        }
        ENDCG
    } }
}
