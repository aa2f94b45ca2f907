Shader "Test/Huge" {
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile _ K0
            #pragma multi_compile _ K1
            #pragma multi_compile _ K2
            #pragma multi_compile _ K3
            #pragma multi_compile _ K4
            #pragma multi_compile _ K5
            #pragma multi_compile _ K6
            #pragma multi_compile _ K7
            #pragma multi_compile _ K8
            #pragma multi_compile _ K9
            #pragma multi_compile _ K10
            #pragma multi_compile _ K11
            #pragma multi_compile _ K12
            #pragma multi_compile _ K13
            #pragma multi_compile _ K14
            #pragma multi_compile _ K15
            #pragma multi_compile _ K16
            #pragma multi_compile _ K17
            #pragma multi_compile _ K18
            #pragma multi_compile _ K19
            #pragma multi_compile _ K20
            #pragma multi_compile _ K21
            #pragma multi_compile _ K22
            #pragma multi_compile _ K23
            #pragma multi_compile _ K24
            #pragma multi_compile _ K25
            #pragma multi_compile _ K26
            #pragma multi_compile _ K27
            #pragma multi_compile _ K28
            #pragma multi_compile _ K29
            #pragma multi_compile _ K30
            #pragma multi_compile _ K31
            #pragma multi_compile _ K32
            #pragma multi_compile _ K33
            #pragma multi_compile _ K34
            #pragma multi_compile _ K35
            #pragma multi_compile _ K36
            #pragma multi_compile _ K37
            #pragma multi_compile _ K38
            #pragma multi_compile _ K39
            float4 vert(float4 p : POSITION) : SV_POSITION { return p; }
            float4 frag() : SV_Target { return 1; }
            ENDCG
        }
    }
}
