// A fragment program whose CRASH_ON variant calls a function the isolation tests' fault hook
// (VARC_TEST_WORKER_FAULT) watches for: its optimiser worker dies or hangs on that program only.
Shader "Test/OptimizerFault" {
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile _ CRASH_ON
            float4 vert(float4 position : POSITION) : SV_POSITION { return position; }
            float4 _Tint;
            float4 OptimizerFaultMarker(float4 colour) {
                float4 sum = 0;
                for (int i = 0; i < 4; ++i) sum += colour * _Tint * (float)i;
                return sum;
            }
            float4 frag() : SV_Target {
            #ifdef CRASH_ON
                return OptimizerFaultMarker(float4(1, 0, 0, 1));
            #else
                return float4(1, 1, 1, 1);
            #endif
            }
            ENDCG
        }
    }
}
