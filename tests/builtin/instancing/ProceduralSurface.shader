// SPDX-License-Identifier: Apache-2.0
// A surface shader drawn with procedural instancing (the pattern of GPU-driven grass and
// particle shaders): the generated passes call the procedural function through
// UNITY_SETUP_INSTANCE_ID (tests/builtin/CMakeLists.txt, builtin.instancing).
Shader "varc-tests/ProceduralSurface" {
    Properties { _MainTex ("Albedo", 2D) = "white" {} }
    SubShader {
        Tags { "RenderType" = "Opaque" }
        CGPROGRAM
        #pragma surface surf Standard addshadow
        #pragma target 4.5
        #pragma multi_compile_instancing
        #pragma instancing_options procedural:setupInstance
        #if defined(UNITY_PROCEDURAL_INSTANCING_ENABLED) && !defined(UNITY_INSTANCING_PROCEDURAL_FUNC)
        #error "the generated passes must see instancing_options procedural:setupInstance"
        #endif
        sampler2D _MainTex;
        struct Input { float2 uv_MainTex; };
        #ifdef UNITY_PROCEDURAL_INSTANCING_ENABLED
        StructuredBuffer<float4x4> _Matrices;
        #endif
        void setupInstance() {
        #ifdef UNITY_PROCEDURAL_INSTANCING_ENABLED
            unity_ObjectToWorld = _Matrices[unity_InstanceID];
        #endif
        }
        void surf(Input IN, inout SurfaceOutputStandard o) {
            o.Albedo = tex2D(_MainTex, IN.uv_MainTex).rgb;
        }
        ENDCG
    }
}
