// SPDX-License-Identifier: Apache-2.0
// An unlit program for the property classification fixtures: half the albedo, no light input.
#ifndef VARC_MUTANT_UNLIT_INCLUDED
#define VARC_MUTANT_UNLIT_INCLUDED

#include "UnityCG.cginc"

float4 _Color;
sampler2D _MainTex;
float4 _MainTex_ST;

struct UnlitAttributes {
    float4 vertex : POSITION;
    float2 texcoord : TEXCOORD0;
};

struct UnlitVaryings {
    float4 pos : SV_POSITION;
    float2 uv : TEXCOORD0;
};

UnlitVaryings UnlitVertex(UnlitAttributes v) {
    UnlitVaryings o;
    o.pos = UnityObjectToClipPos(v.vertex);
    o.uv = TRANSFORM_TEX(v.texcoord, _MainTex);
    return o;
}

// Half the albedo; UNLIT_NOTHING (a ForwardAdd pass that lights nothing) draws black.
float4 UnlitFragment(UnlitVaryings i) : SV_Target {
    float4 albedo = tex2D(_MainTex, i.uv) * _Color;
#if defined(UNLIT_NOTHING)
    return float4(0, 0, 0, albedo.a);
#else
    return float4(0.5 * albedo.rgb, 1);
#endif
}

#endif // VARC_MUTANT_UNLIT_INCLUDED
