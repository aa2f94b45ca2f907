// SPDX-License-Identifier: Apache-2.0
// builtin.longtail-includes: UI Toolkit's default programs (UnityUIE.cginc's vert / frag) at
// Shader Model 2 (constants) and 3.5 (shader-info texture, 8 texture slots), a custom UIE shader
// and the editor's (EditorUIE.cginc), in gamma and linear colour space.
Shader "Test/Longtail/UIElements" {
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 2.0
            #pragma multi_compile _ UNITY_COLORSPACE_GAMMA
            #include "UnityUIE.cginc"
            ENDCG
        }
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 3.5
            #include "UnityUIE.cginc"
            ENDCG
        }
        Pass {
            CGPROGRAM
            #pragma vertex customVert
            #pragma fragment customFrag
            #pragma target 3.5
            #define UIE_CUSTOM_SHADER
            #include "UnityUIE.cginc"
            v2f customVert(appdata_t v) {
                float4 clipSpacePos;
                v2f o = uie_std_vert(v, clipSpacePos);
                o.pos.xy = uie_snap_to_integer_pos(clipSpacePos.xy);
                return o;
            }
            UIE_FRAG_T customFrag(v2f i) : SV_Target {
                float2 p = i.uvClip.xy * 2 - 1;
                float flags = 5;
                float bit = TestForValue(4, flags);
                UIE_FRAG_T c = uie_std_frag(i);
                c.a *= sdf(i.uvClip.x) * ComputeCoverage(p, p * 2) * bit;
                c.rgb += (UIE_FRAG_SCALAR_T)uie_radial_address(p, float2(0.25, 0));
                return c;
            }
            ENDCG
        }
        Pass {
            CGPROGRAM
            #pragma vertex editorVert
            #pragma fragment editorFrag
            #pragma target 3.5
            #include "EditorUIE.cginc"
            // Wrappers: uie_std_vert is overloaded, and an overloaded entry point fails
            // `varc build` without a diagnostic.
            v2f editorVert(appdata_t v) {
                return uie_std_vert(v);
            }
            fixed4 editorFrag(v2f i) : SV_Target {
                return uie_editor_frag(i);
            }
            ENDCG
        }
    }
}
