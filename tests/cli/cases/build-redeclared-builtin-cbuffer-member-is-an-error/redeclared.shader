Shader "Test/Redeclared" { SubShader { Pass {
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
fixed3 _LightColor0;
float4 vert(float4 v : POSITION) : SV_POSITION { return v; }
float4 frag() : SV_Target { return float4(_LightColor0, 1); }
ENDCG
} } }
