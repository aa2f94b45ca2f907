Shader "Case/Lit" {
    SubShader {
        Pass {
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            float4 vert(float4 p : POSITION) : SV_POSITION { return UnityObjectToClipPos(p); }
            fixed4 frag() : SV_Target { return 1; }
            ENDCG
        }
        UsePass "Case/Outline/OUTLINE"
    }
    Fallback "Diffuse"
}
