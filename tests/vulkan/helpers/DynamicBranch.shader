// SPDX-License-Identifier: Apache-2.0
// dynamic_branch keywords end to end (tests/vulkan/DynamicBranchTest.cpp): one program whose
// `if (K)` branches follow the keywords the draw enables, beside a multi_compile keyword that
// still selects a variant. Pass 0 draws the test quad as given, pass 1 is the ForwardBase pass
// the scene renderer draws a sphere with. The test computes every branch on the CPU.
Shader "varc-test/DynamicBranch" {
    Properties {
        _Tint ("Tint", Color) = (0.2, 0.4, 0.6, 1)
    }
    CGINCLUDE
    #include "UnityCG.cginc"
    float4 _Tint;

    struct Interpolators {
        float4 pos : SV_POSITION;
        float2 uv : TEXCOORD0;
    };

    float4 shade(float2 uv) {
        float4 c = float4(_Tint.r, _Tint.g, uv.x, uv.y);
        if (RED) c.r = 1.0 - 0.5 * _Tint.r;
        if (GREEN) c.g = _Tint.g * _Tint.g + 0.5;
        if (WAVE) {
            c.b = uv.x * uv.y;
        }
    #ifdef RED
        c = 0.0;  // RED is a uniform, never a macro: this line is dead whatever the draw enables
    #endif
    #ifdef HALF
        c.rgb *= 0.5;
    #endif
        return c;
    }
    ENDCG
    SubShader {
        Pass {
            Cull Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma dynamic_branch_local _ RED GREEN
            #pragma dynamic_branch WAVE
            #pragma multi_compile _ HALF
            Interpolators vert(float4 vertex : POSITION, float2 uv : TEXCOORD0) {
                Interpolators i;
                i.pos = float4(vertex.xy, 0.5, 1.0);
                i.uv = uv;
                return i;
            }
            float4 frag(Interpolators i) : SV_Target { return shade(i.uv); }
            ENDCG
        }
        Pass {
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma dynamic_branch_local _ RED GREEN
            #pragma dynamic_branch WAVE
            #pragma multi_compile _ HALF
            Interpolators vert(float4 vertex : POSITION, float2 uv : TEXCOORD0) {
                Interpolators i;
                i.pos = UnityObjectToClipPos(vertex);
                i.uv = uv;
                return i;
            }
            float4 frag(Interpolators i) : SV_Target { return shade(i.uv); }
            ENDCG
        }
    }
}
