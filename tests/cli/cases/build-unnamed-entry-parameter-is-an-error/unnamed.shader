Shader "Test/Unnamed" { SubShader { Pass {
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
float4 vert(float4 : POSITION) : SV_POSITION { return 0; }
float4 frag() : SV_Target { return 1; }
ENDCG
} } }
