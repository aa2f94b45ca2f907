Shader "T/Recurse" { SubShader { Pass {
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
#define A B
#define B A
#define F(x) G(x)
#define G(x) F(x)
#define H(x) H(H(x))
float4 vert(float4 v : POSITION) : SV_POSITION { return v; }
fixed4 frag() : SV_Target { float A = 1; return F(A) + H(1); }
ENDCG
} } }
