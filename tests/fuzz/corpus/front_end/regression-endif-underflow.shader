Shader "T/Endif" { SubShader { Pass {
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
#endif
#endif
#else
#elif 1
float4 vert(float4 v : POSITION) : SV_POSITION { return v; }
fixed4 frag() : SV_Target { return 1; }
ENDCG
} } }
