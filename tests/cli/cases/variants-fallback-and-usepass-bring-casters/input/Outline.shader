Shader "Case/Outline" {
    SubShader {
        Pass {
            Name "Outline"
            Cull Front
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            float4 vert(float4 p : POSITION) : SV_POSITION { return UnityObjectToClipPos(p); }
            fixed4 frag() : SV_Target { return 0; }
            ENDCG
        }
    }
    Fallback "Toon/Missing"
}
