// A dynamic_branch keyword tested both ways: `if (FAST)` branches at run time, `#ifdef FAST`
// is always false (FAST is a uniform, never a macro) and gets a warning.
Shader "Test/DynamicBranch" {
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma dynamic_branch FAST
            #pragma multi_compile _ TINT
            float4 vert(float4 v : POSITION) : SV_POSITION { return v; }
            float4 frag() : SV_Target {
                float4 c = 0.25;
                if (FAST) c = 0.5;
            #ifdef FAST
                c = 1.0;
            #endif
                return c;
            }
            ENDCG
        }
    }
}
