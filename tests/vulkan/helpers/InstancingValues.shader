// SPDX-License-Identifier: Apache-2.0
// Evaluates the instancing plumbing of UnityInstancing.cginc (issue #27) at every pixel of a
// full-target quad drawn as instance 0, so that tests/vulkan/InstancingValueTest.cpp can compare
// lavapipe's result with the values it set: the draw's matrices and block (no keyword), the
// per-instance arrays (INSTANCING_ON) and the procedural function (PROCEDURAL_INSTANCING_ON).
// Pixel centre (u, v) in (0, 1)^2 is the input.
Shader "Test/InstancingValues" {
    SubShader {
        Pass {
            Cull Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 4.5
            #pragma multi_compile_instancing
            #pragma instancing_options procedural:setupInstance
            #pragma multi_compile _ IV_CLIP
            #include "UnityCG.cginc"

            UNITY_INSTANCING_BUFFER_START(Props)
                UNITY_DEFINE_INSTANCED_PROP(float4, _Tint)
            UNITY_INSTANCING_BUFFER_END(Props)

            // The procedural function: moves the draw's matrix by 1.5 along x, scales y by 3 and
            // sets the tint from the instance ID.
            void setupInstance() {
            #ifdef UNITY_PROCEDURAL_INSTANCING_ENABLED
                unity_ObjectToWorld[0][3] += 1.5;
                unity_ObjectToWorld[1][1] *= 3.0;
                _Tint = float4(7.0 + unity_InstanceID, 0.5, 0.25, 1.0);
            #endif
            }

            struct appdata {
                float4 vertex : POSITION;
                float2 uv : TEXCOORD0;
                UNITY_VERTEX_INPUT_INSTANCE_ID
            };
            struct v2f {
                float4 pos : SV_POSITION;
                float2 uv : TEXCOORD0;
                UNITY_VERTEX_INPUT_INSTANCE_ID
            };

            v2f vert(appdata v) {
                v2f o;
                UNITY_SETUP_INSTANCE_ID(v);
                UNITY_INITIALIZE_OUTPUT(v2f, o);
                UNITY_TRANSFER_INSTANCE_ID(v, o);
                o.pos = float4(v.vertex.xy, 0.5, 1.0);
                o.uv = v.uv;
                return o;
            }

            float4 frag(v2f i) : SV_Target {
                UNITY_SETUP_INSTANCE_ID(i);
                float4 p = float4(i.uv, 0.25, 1.0);
            #ifdef IV_CLIP
                return UnityObjectToClipPos(p.xyz);
            #else
                return float4(mul(unity_ObjectToWorld, p).xyz, UNITY_ACCESS_INSTANCED_PROP(Props, _Tint).x * i.uv.x);
            #endif
            }
            ENDCG
        }
    }
}
