// SPDX-License-Identifier: Apache-2.0
// Procedural instancing as Unity's manual shows it for Graphics.DrawMeshInstancedIndirect: a
// per-instance buffer read in the procedural function, which sets the instance's matrices
// (tests/builtin/CMakeLists.txt, builtin.instancing). The #error lines fail the build when
// `#pragma instancing_options` did not reach the program.
Shader "varc-tests/ProceduralInstancing" {
    Properties { _Color ("Color", Color) = (1, 1, 1, 1) }
    SubShader {
        Pass {
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 4.5
            #pragma multi_compile_instancing
            #pragma instancing_options procedural:setup maxcount:64 assumeuniformscaling
            #include "UnityCG.cginc"

            #if UNITY_MAX_INSTANCE_COUNT != 64 || !defined(UNITY_ASSUME_UNIFORM_SCALING)
            #error "instancing_options maxcount:64 assumeuniformscaling did not reach the program"
            #endif
            #if defined(PROCEDURAL_INSTANCING_ON) && !defined(UNITY_PROCEDURAL_INSTANCING_ENABLED)
            #error "PROCEDURAL_INSTANCING_ON at target 4.5 must enable procedural instancing"
            #endif
            #if defined(UNITY_PROCEDURAL_INSTANCING_ENABLED) && defined(UNITY_INSTANCING_ENABLED)
            #error "procedural instancing is not array instancing"
            #endif

            #ifdef UNITY_PROCEDURAL_INSTANCING_ENABLED
            StructuredBuffer<float4> _Positions;   // xyz position, w uniform scale
            #endif
            UNITY_INSTANCING_BUFFER_START(Props)
                UNITY_DEFINE_INSTANCED_PROP(float4, _Color)
            UNITY_INSTANCING_BUFFER_END(Props)

            void setup() {
            #ifdef UNITY_PROCEDURAL_INSTANCING_ENABLED
                float4 data = _Positions[unity_InstanceID];
                unity_ObjectToWorld = float4x4(data.w, 0, 0, data.x, 0, data.w, 0, data.y, 0, 0, data.w, data.z, 0, 0, 0, 1);
                unity_WorldToObject = unity_ObjectToWorld;
                unity_WorldToObject._14_24_34 *= -1;
                unity_WorldToObject._11_22_33 = 1.0f / unity_WorldToObject._11_22_33;
                _Color = float4(frac(data.xyz), 1);
            #endif
            }

            struct appdata {
                float4 vertex : POSITION;
                float3 normal : NORMAL;
                UNITY_VERTEX_INPUT_INSTANCE_ID
            };
            struct v2f {
                float4 pos : SV_POSITION;
                float3 normal : TEXCOORD0;
                UNITY_VERTEX_INPUT_INSTANCE_ID
                UNITY_VERTEX_OUTPUT_STEREO
            };
            v2f vert(appdata v) {
                v2f o;
                UNITY_SETUP_INSTANCE_ID(v);
                UNITY_INITIALIZE_OUTPUT(v2f, o);
                UNITY_TRANSFER_INSTANCE_ID(v, o);
                UNITY_INITIALIZE_VERTEX_OUTPUT_STEREO(o);
                o.pos = UnityObjectToClipPos(v.vertex);
                o.normal = UnityObjectToWorldNormal(v.normal);
                return o;
            }
            fixed4 frag(v2f i) : SV_Target {
                UNITY_SETUP_INSTANCE_ID(i);
                UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX(i);
                return UNITY_ACCESS_INSTANCED_PROP(Props, _Color) * saturate(i.normal.y * 0.5 + 0.5);
            }
            ENDCG
        }
    }
}
