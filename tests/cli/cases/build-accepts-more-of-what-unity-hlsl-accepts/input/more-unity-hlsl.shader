Shader "Test/MoreUnityHlsl" {
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            #define DECLARE(suffix) float _Blend##suffix;
            #define DECLARE_WEIGHT(suffix) float _Weight##suffix;
            CBUFFER_START(UnityPerMaterial)
                sampler2D _Ramp;                      // a texture in a cbuffer
                DECLARE(##)                           // the old-Unity spelling of ""
                DECLARE(Offset)
                DECLARE_WEIGHT()                      // an empty argument (C99, Unity 2020.3+)
                float4 _Ramp_ST;
            CBUFFER_END
            float3x3 _From, _To;
            struct V2F { float4 pos : SV_POSITION; float4 uv : TEXCOORD0; };
            V2F fill(V2F o, float4 p) { o.pos = UnityObjectToClipPos(p.xyz); o.uv = p; return o; }
            V2F vert(float4 p : POSITION) {
                V2F o = fill(o, p);                   // a local named in its own initializer
                return o;
            }
            float scale(float x) { return x * 2; }
            float4 frag(V2F i, fixed facing : VFACE) : SV_Target {   // a D3D9 face register
            #ifdef GL_ARB_gpu_shader5
                return undeclaredOnPurpose;           // glslang's GLSL macros stay unseen
            #endif
                float3x3 m = lerp(_From, _To, _Blend);             // lerp on matrices
                float s = scale(tex2D(_Ramp, i.uv.xy * _Ramp_ST.xy)); // float4 -> float
                return float4(mul(m, i.uv.xyz) * s * facing * _Weight + _BlendOffset, 1);
            }
            ENDCG
        }
    }
}
