Shader "FuzzBuild/ArrayOfAGlobal" { SubShader { Pass {
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
float4 _A;
float4 _A[ST;
float4 vert(float4 p : POSITION) : SV_Position { return p * _A; }
float4 frag() : SV_Target { return 1; }
ENDCG
} } }
