Shader "Test/FxcWrittenParameters" {
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            struct V2F { float4 pos : SV_POSITION; float4 uv : TEXCOORD0; float3 normal : NORMAL; };
            V2F vert(appdata_base v, uint vid : SV_VertexID) {
                v.vertex.xyz *= 2;                 // inputs are copies: writable, as in FXC
                vid += 1;
                V2F o;
                o.pos = UnityObjectToClipPos(v.vertex.xyz);
                o.uv = v.texcoord + vid;
                o.normal = v.normal;
                return o;
            }
            // `uniform` parameters are globals to FXC, which lets the code write them (a copy).
            float4 frag(V2F i, uniform float4 _Tint) : SV_Target {
                _Tint.a *= 0.5;
                i.uv.x += 1;
                i.normal = normalize(i.normal);
                return float4(i.normal * i.uv.x, 1) * _Tint;
            }
            ENDCG
        }
    }
}
