Shader "FuzzBuild/Redeclared" { SubShader { Pass {
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
sampler2D _A;
float4 _A;
float4 vert(float4 v : POSITION) : SV_POSITION { return v; }
float4 frag() : SV_Target { return _A; }
ENDCG
} } }
