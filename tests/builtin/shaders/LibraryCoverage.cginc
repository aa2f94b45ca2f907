// SPDX-License-Identifier: Apache-2.0
// Test program for tests/builtin: a forward-lit program that touches most of the built-in CG
// library (UnityCG, Lighting, AutoLight, UnityPBSLighting, instancing, fog), so that every
// keyword combination of the test list compiles against shaders/builtin.
#ifndef VARC_TEST_LIBRARY_COVERAGE_INCLUDED
#define VARC_TEST_LIBRARY_COVERAGE_INCLUDED

#include "UnityCG.cginc"
#include "Lighting.cginc"
#include "AutoLight.cginc"
#include "UnityPBSLighting.cginc"

sampler2D _MainTex;
float4 _MainTex_ST;
sampler2D _BumpMap;
half _Metallic;
half _Glossiness;

UNITY_INSTANCING_BUFFER_START(Props)
    UNITY_DEFINE_INSTANCED_PROP(fixed4, _Color)
UNITY_INSTANCING_BUFFER_END(Props)

struct v2f {
    float4 pos : SV_POSITION;
    float2 uv : TEXCOORD0;
    float3 worldPos : TEXCOORD1;
    half3 worldNormal : TEXCOORD2;
    half3 vertexLight : TEXCOORD3;
    UNITY_LIGHTING_COORDS(4, 5)
    UNITY_FOG_COORDS(6)
    UNITY_VERTEX_INPUT_INSTANCE_ID
};

v2f vert(appdata_full v) {
    v2f o;
    UNITY_INITIALIZE_OUTPUT(v2f, o);
    UNITY_SETUP_INSTANCE_ID(v);
    UNITY_TRANSFER_INSTANCE_ID(v, o);
    o.pos = UnityObjectToClipPos(v.vertex);
    o.uv = TRANSFORM_TEX(v.texcoord, _MainTex);
    o.worldPos = mul(unity_ObjectToWorld, v.vertex).xyz;
    o.worldNormal = UnityObjectToWorldNormal(v.normal);
    o.vertexLight = 0;
#if defined(VERTEXLIGHT_ON)
    o.vertexLight = Shade4PointLights(unity_4LightPosX0, unity_4LightPosY0, unity_4LightPosZ0,
        unity_LightColor[0].rgb, unity_LightColor[1].rgb, unity_LightColor[2].rgb, unity_LightColor[3].rgb,
        unity_4LightAtten0, o.worldPos, o.worldNormal);
    o.vertexLight += ShadeVertexLights(v.vertex, v.normal) * 0;
#endif
    UNITY_TRANSFER_LIGHTING(o, v.texcoord1.xy);
    UNITY_TRANSFER_FOG(o, o.pos);
    return o;
}

fixed4 frag(v2f i) : SV_Target {
    UNITY_SETUP_INSTANCE_ID(i);
    fixed4 tint = UNITY_ACCESS_INSTANCED_PROP(Props, _Color);
    half3 albedo = tex2D(_MainTex, i.uv).rgb * tint.rgb;
    half3 n = normalize(i.worldNormal + UnpackNormal(tex2D(_BumpMap, i.uv)) * 0.01);
    float3 viewDir = normalize(UnityWorldSpaceViewDir(i.worldPos));

    UNITY_LIGHT_ATTENUATION(atten, i, i.worldPos);
    UnityGI gi;
    gi.light.color = _LightColor0.rgb * atten;
    gi.light.dir = normalize(UnityWorldSpaceLightDir(i.worldPos));
    gi.light.ndotl = LambertTerm(n, gi.light.dir);
    gi.indirect.diffuse = i.vertexLight;
#if UNITY_SHOULD_SAMPLE_SH
    gi.indirect.diffuse += ShadeSHPerPixel(n, half3(0, 0, 0), i.worldPos);
#endif
    gi.indirect.specular = unity_IndirectSpecColor.rgb;

    SurfaceOutputStandard s;
    s.Albedo = albedo;
    s.Normal = n;
    s.Emission = 0;
    s.Metallic = _Metallic;
    s.Smoothness = _Glossiness;
    s.Occlusion = 1;
    s.Alpha = tint.a;
    fixed4 c = LightingStandard(s, viewDir, gi);

    SurfaceOutput legacy;
    legacy.Albedo = albedo;
    legacy.Normal = n;
    legacy.Emission = 0;
    legacy.Specular = 0.5;
    legacy.Gloss = 1;
    legacy.Alpha = 1;
    c.rgb += 0.001 * (LightingBlinnPhong(legacy, viewDir, gi).rgb + LightingLambert(legacy, gi).rgb);
    c.rgb += 0.001 * GammaToLinearSpace(LinearToGammaSpace(c.rgb)) * Luminance(c.rgb);
    c.a *= DecodeFloatRGBA(EncodeFloatRGBA(0.5)) + LinearEyeDepth(i.pos.z) * 0;
    UNITY_APPLY_FOG(i.fogCoord, c);
    return c;
}

#endif
