Shader "Test/FxcScalarAnyAll" {
    SubShader {
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #include "UnityCG.cginc"
            struct V2F { float4 pos : SV_POSITION; float4 uv : TEXCOORD0; nointerpolation int2 id : TEXCOORD1; };
            V2F vert(float4 p : POSITION, uint vid : SV_VertexID) {
                V2F o;
                o.pos = UnityObjectToClipPos(p.xyz);
                o.uv = p;
                o.id = int2(vid, 0);
                return o;
            }
            float4 frag(V2F i) : SV_Target {
                float4 c = 1;
                if (any(i.uv.x)) c.r = 0;          // any/all of a scalar: "is it non-zero"
                if (all(i.id.x)) c.g = 0;
                if (any(i.uv.y > 0.5)) c.b = 0;
                if (all(i.uv.xy)) c.a = 0;        // vectors, as glslang compiles them already
                if (any(i.id)) c.a = 1;
                return c;
            }
            ENDCG
        }
    }
}
