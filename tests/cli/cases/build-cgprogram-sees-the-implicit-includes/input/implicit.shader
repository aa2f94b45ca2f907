Shader "Test/ImplicitIncludes" {
    CGINCLUDE
    fixed4 _Color;   // HLSLSupport.cginc's fixed4, before any #include, as Unity allows
    ENDCG
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            float4 vert(float4 p : POSITION) : SV_POSITION { return UnityObjectToClipPos(p.xyz); }
            fixed4 frag() : SV_Target { return _Color * _Time.y; }
            ENDCG
        }
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            // No #include at all: UnityShaderVariables.cginc's matrices and _Time are still there.
            float4 vert(float4 p : POSITION) : SV_POSITION {
                return mul(UNITY_MATRIX_VP, mul(unity_ObjectToWorld, p));
            }
            fixed4 frag() : SV_Target { return _Color * _SinTime.w; }
            ENDCG
        }
    }
}
