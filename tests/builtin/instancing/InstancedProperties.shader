// SPDX-License-Identifier: Apache-2.0
// GPU instancing as Unity's manual documents it for vertex/fragment shaders: per-instance
// properties, instance IDs carried to the fragment stage, LOD cross-fade, stereo instancing and
// the legacy block spellings (tests/builtin/CMakeLists.txt, builtin.instancing).
Shader "varc-tests/InstancedProperties" {
    Properties {
        _Color ("Color", Color) = (1, 1, 1, 1)
        _Glow ("Glow", Float) = 0
    }
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 3.5
            #pragma multi_compile_instancing
            #pragma multi_compile _ LOD_FADE_CROSSFADE
            #pragma multi_compile _ STEREO_INSTANCING_ON
            #pragma instancing_options lodfade forcemaxcount:32 nolightprobe nolightmap
            #include "UnityCG.cginc"

            #if UNITY_INSTANCED_ARRAY_SIZE != 32
            #error "instancing_options forcemaxcount:32 did not size the arrays"
            #endif
            #if defined(INSTANCING_ON) && defined(LOD_FADE_CROSSFADE) && !defined(UNITY_USE_LODFADE_ARRAY)
            #error "instancing_options lodfade must instance unity_LODFade"
            #endif
            #if defined(UNITY_USE_SHCOEFFS_ARRAYS) || defined(UNITY_USE_LIGHTMAPST_ARRAY)
            #error "light probes and lightmaps stay per draw"
            #endif
            #if defined(STEREO_INSTANCING_ON) != defined(UNITY_STEREO_INSTANCING_ENABLED)
            #error "STEREO_INSTANCING_ON at target 3.5 enables stereo instancing"
            #endif

            UNITY_INSTANCING_BUFFER_START(Props)
                UNITY_DEFINE_INSTANCED_PROP(fixed4, _Color)
            UNITY_INSTANCING_BUFFER_END(Props)
            // Unity 5.6's spelling of a per-instance block.
            UNITY_INSTANCING_CBUFFER_START(MoreProps)
                UNITY_DEFINE_INSTANCED_PROP(float, _Glow)
            UNITY_INSTANCING_CBUFFER_END

            struct appdata {
                float4 vertex : POSITION;
                UNITY_VERTEX_INPUT_INSTANCE_ID
            };
            struct v2f {
                float4 pos : SV_POSITION;
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
                return o;
            }
            fixed4 frag(v2f i) : SV_Target {
                UNITY_SETUP_INSTANCE_ID(i);
                UNITY_SETUP_STEREO_EYE_INDEX_POST_VERTEX(i);
                UNITY_APPLY_DITHER_CROSSFADE(i.pos.xy);
                return UNITY_ACCESS_INSTANCED_PROP(Props, _Color)
                     + UNITY_ACCESS_INSTANCED_PROP(MoreProps, _Glow) * unity_LODFade.x
                     + unity_StereoEyeIndex * 0.01 + unity_RenderingLayer.x * 0.0;
            }
            ENDCG
        }
    }
}
