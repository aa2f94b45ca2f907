Shader "T/UsesInclude" { SubShader { Pass {
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
#include "broken.cginc"
float4 vert(float4 v : POSITION) : SV_POSITION { return v; }
fixed4 frag() : SV_Target { return tint(fixed4(1, 0, 0, 1)); }
ENDCG
} } }
