Shader "Test/UnityHlsl" {
    SubShader {
        Pass {
            ZTest Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile_fwdbadd
            #define UNITY_PASS_FORWARDBASE
            #include "UnityCG.cginc"
            #define HALF_TURN 3.14
            #define HALF_TURN 3.1416                  // redefined: Unity warns, the later wins
            float _Mode;
            float4 _Tint;
            float4 vert(float4 p : POSITION) : SV_POSITION { return UnityObjectToClipPos(p.xyz); }
            float4 frag() : SV_Target {
                _Tint.a = 1;                          // a uniform written: a per-invocation copy
                float3 forward = UNITY_MATRIX_V._m20_m21_m22;  // a matrix swizzle
                switch (_Mode) {                      // a switch on a float
                    case 1: return float4(forward, GetRenderTargetSampleCount());
                    default: return _Tint * HALF_TURN;
                }
            }
            ENDCG
        }
    }
}
