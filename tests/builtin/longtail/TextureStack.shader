// SPDX-License-Identifier: Apache-2.0
// builtin.longtail-includes: texture stacks (UnityLegacyTextureStack.cginc) with and without
// UNITY_VIRTUAL_TEXTURING, clamped and not, in the vertex (level sampling) and fragment stages.
Shader "Test/Longtail/TextureStack" {
    Properties {
        _MainTex ("Albedo", 2D) = "white" {}
        _BumpMap ("Normal", 2D) = "bump" {}
    }
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile _ UNITY_VIRTUAL_TEXTURING
            #pragma multi_compile _ TEXTURESTACK_CLAMP
            #include "UnityCG.cginc"
            #include "UnityLegacyTextureStack.cginc"
            sampler2D _MainTex;
            sampler2D _BumpMap;
            sampler2D _Detail;
            sampler2D _Mask;
            CBUFFER_START(UnityPerMaterial)
                float4 _MainTex_ST;
                DECLARE_STACK_CB(_Stack)
            CBUFFER_END
            DECLARE_STACK2(_Stack, _MainTex, _BumpMap);
            DECLARE_STACK(_Single, _MainTex)
            DECLARE_STACK3(_Three, _MainTex, _BumpMap, _Detail)
            DECLARE_STACK4(_Four, _MainTex, _BumpMap, _Detail, _Mask)
            struct v2f {
                float4 pos : SV_POSITION;
                float2 uv : TEXCOORD0;
                float4 lod : TEXCOORD1;
            };
            v2f vert(float4 vertex : POSITION, float2 uv : TEXCOORD0) {
                v2f o;
                o.pos = UnityObjectToClipPos(vertex);
                o.uv = TRANSFORM_TEX(uv, _MainTex);
                StackInfo info = PrepareStackLod(o.uv, _Stack, 2);
                o.lod = SampleStackLod(info, _MainTex) + float4(SampleStackLodNormal(info, _BumpMap, 0.5), 0);
                return o;
            }
            struct fout {
                float4 color : SV_Target0;
                float4 feedback : SV_Target1;
            };
            fout frag(v2f i) {
                StackInfo info = PrepareStack(i.uv, _Stack);
                float3 n = SampleStackNormal(info, _BumpMap, 1.0);
                fout o;
                o.color = SampleStack(info, _MainTex) * saturate(n.z) + i.lod;
                o.feedback = PackResolveOutput(GetResolveOutput(info)) + ResolveStack(i.uv, _Stack);
                return o;
            }
            ENDCG
        }
    }
}
