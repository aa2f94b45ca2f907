// SPDX-License-Identifier: Apache-2.0
// varc built-in: the legacy VertexLit shader as a fallback. Shaders name it (`Fallback
// "VertexLit"`, `UsePass "VertexLit/SHADOWCASTER"`) for its shadow caster, which is what varc
// ships: depth maps for directional and spot lights, depth cube maps for point lights, with the
// light's linear and normal-offset biases (UnityCG.cginc's caster macros, docs/LIGHTING.md §6).
// Written for varc.
Shader "Legacy Shaders/VertexLit" {
    Properties {
        _Color ("Main Color", Color) = (1, 1, 1, 1)
        _MainTex ("Base (RGB)", 2D) = "white" {}
    }
    SubShader {
        Tags { "RenderType" = "Opaque" }
        Pass {
            Name "ShadowCaster"
            Tags { "LightMode" = "ShadowCaster" }
            ZWrite On ZTest LEqual Cull Back
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile_shadowcaster
            #include "UnityCG.cginc"

            struct v2f {
                V2F_SHADOW_CASTER;
            };

            v2f vert(appdata_base v) {
                v2f o;
                TRANSFER_SHADOW_CASTER_NORMALOFFSET(o)
                return o;
            }

            float4 frag(v2f i) : SV_Target {
                SHADOW_CASTER_FRAGMENT(i)
            }
            ENDCG
        }
    }
}
