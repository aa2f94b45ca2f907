Shader "T/Chain" { SubShader { Pass {
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
#include "outer.cginc"
float4 vert(float4 v : POSITION) : SV_POSITION { return v; }
fixed4 frag() : SV_Target { return 1; }
ENDCG
} } }
