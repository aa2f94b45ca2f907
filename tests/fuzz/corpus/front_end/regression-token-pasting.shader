Shader "T/Paste" { SubShader { Pass {
CGPROGRAM
#pragma vertex vert
#pragma fragment frag
#define CAT(a,b) a##b
#define CAT3(a,b,c) a ## b ## c
#define BAD(a) ## a
#define BAD2(a) a ##
float4 CAT(ve,rt)(float4 v : POSITION) : SV_POSITION { return v; }
fixed4 frag() : SV_Target { return CAT3(1,.,5) + CAT(,1) + CAT(0x, ) ; }
ENDCG
} } }
