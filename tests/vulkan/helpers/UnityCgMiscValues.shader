// SPDX-License-Identifier: Apache-2.0
// Runs UnityCG.cginc's vertex helpers (pixel snapping, the shadow-caster position with its normal
// offset and linear bias and the TRANSFER_SHADOW_CASTER macros, vert_img, COMPUTE_EYEDEPTH and
// UNITY_OPAQUE_ALPHA) over a full-target quad for tests/vulkan/UnityCgMiscValueTest.cpp, with
// inputs made from the pixel centre (s, t); each variant writes four floats.
Shader "Test/UnityCgMiscValues" {
    SubShader {
        Pass {
            Cull Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile CM_SNAP CM_CASTER CM_CASTER_MACROS CM_IMG CM_EYEDEPTH
            #include "UnityCG.cginc"

            struct Interpolators {
                float4 pos : SV_POSITION;
                float2 uv : TEXCOORD0;
            };
            struct CasterOutput {
                float4 pos;
            };

            Interpolators vert(float4 vertex : POSITION, float2 uv : TEXCOORD0) {
                Interpolators i;
                i.pos = float4(vertex.xy, 0.5, 1.0);
                i.uv = uv;
                return i;
            }

            // The object-space vertex and normal the caster and depth groups use (the macros
            // read them from a local named v, as in a vertex program).
            appdata_base testVertex(float s, float t) {
                appdata_base v = (appdata_base)0;
                v.vertex = float4(s - 0.5, t - 0.5, 0.2 + 0.3 * s, 1.0);
                v.normal = normalize(float3(0.3, s - 0.5, 1.0 - t));
                return v;
            }

            float4 frag(Interpolators i) : SV_Target {
                float s = i.uv.x, t = i.uv.y;
            #if defined(CM_SNAP)
                float w = 1.5 + s;
                return UnityPixelSnap(float4(0.93 * (2.0 * s - 1.0) * w, 0.93 * (2.0 * t - 1.0) * w, 0.3, w));
            #elif defined(CM_CASTER)
                appdata_base v = testVertex(s, t);
                float4 a = UnityClipSpaceShadowCasterPos(v.vertex, v.normal);
                float4 b = UnityClipSpaceShadowCasterPos(v.vertex.xyz, v.normal);
                return float4(a.xy, b.zw);
            #elif defined(CM_CASTER_MACROS)
                appdata_base v = testVertex(s, t);
                CasterOutput o;
                TRANSFER_SHADOW_CASTER(o);
                float z0 = o.pos.z;
                TRANSFER_SHADOW_CASTER_NORMALOFFSET(o);
                float z1 = o.pos.z;
                float4 opos;
                TRANSFER_SHADOW_CASTER_NOPOS(o, opos);
                float4 legacy;
                TRANSFER_SHADOW_CASTER_NOPOS_LEGACY(o, legacy);
                return float4(z0, z1, opos.z, legacy.w);
            #elif defined(CM_IMG)
                appdata_img a = (appdata_img)0;
                a.vertex = float4(s - 0.5, t, 0.25, 1.0);
                a.texcoord = float2(t, s);
                v2f_img o = vert_img(a);
                return float4(o.pos.x, o.pos.w, o.uv);
            #else // CM_EYEDEPTH
                appdata_base v = testVertex(s, t);
                float depth;
                COMPUTE_EYEDEPTH(depth);
                float alpha = 0.25 * s;
                UNITY_OPAQUE_ALPHA(alpha);
                return float4(depth, alpha, 0, 0);
            #endif
            }
            ENDCG
        }
    }
}
