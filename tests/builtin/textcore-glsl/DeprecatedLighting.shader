// SPDX-License-Identifier: Apache-2.0
// A 5.x-era lighting shader calling the helpers Unity moved to UnityDeprecated.cginc (through
// UnityStandardBRDF.cginc and UnityImageBasedLighting.cginc, as in Unity), with the gamma-space
// light constants in one variant. builtin.textcore-glsl builds every variant. Written for varc's
// tests.
Shader "varc-tests/DeprecatedLighting" {
    Properties {
        _Color ("Colour", Color) = (1, 1, 1, 1)
        _Roughness ("Perceptual roughness", Range(0, 1)) = 0.5
        _Cube ("Environment", Cube) = "" {}
    }
    SubShader {
        Pass {
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile __ UNITY_COLORSPACE_GAMMA
            #include "UnityCG.cginc"
            #include "UnityStandardBRDF.cginc"
            #include "UnityImageBasedLighting.cginc"
            #include "UnityLightingCommon.cginc"

            half4 _Color;
            half _Roughness;
            UNITY_DECLARE_TEXCUBE(_Cube);
            half4 _Cube_HDR;

            struct v2f {
                float4 pos : SV_POSITION;
                float3 normal : TEXCOORD0;
                float3 view : TEXCOORD1;
            };

            v2f vert(appdata_base v) {
                v2f o;
                o.pos = UnityObjectToClipPos(v.vertex);
                o.normal = UnityObjectToWorldNormal(v.normal);
                o.view = WorldSpaceViewDir(v.vertex);
                return o;
            }

            half4 frag(v2f i) : SV_Target {
                half3 n = normalize(i.normal), v = normalize(i.view), l = _WorldSpaceLightPos0.xyz;
                half3 h = normalize(l + v);
                half nl = LambertTerm(n, l), nv = DotClamped(n, v), nh = BlinnTerm(n, h);
                half lh = DotClamped(l, h), vh = DotClamped(v, h);
                half visibility = SmithGGXVisibilityTerm(nl, nv, _Roughness) + CookTorranceVisibilityTerm(nl, nv, nh, vh)
                                + KelemenVisibilityTerm(lh) + ModifiedKelemenVisibilityTerm(lh, _Roughness)
                                + ImplicitVisibilityTerm();
                half d = RDFBlinnPhongNormalizedTerm(nh, RoughnessToSpecPower(_Roughness));
                half3 f = SebLagardeFresnelTerm(_Color.rgb, _Roughness, nv) + LazarovFresnelTerm(_Color.rgb, _Roughness, nv);
                half3 env = Unity_GlossyEnvironment(UNITY_PASS_TEXCUBE(_Cube), _Cube_HDR, reflect(-v, n), _Roughness);
                env += DecodeHDR_NoLinearSupportInSM2(half4(env, 1), _Cube_HDR);
                half3 c = _Color.rgb * nl + d * visibility * f * unity_LightGammaCorrectionConsts_PIDiv4 * _LightColor0.rgb;
                c += env * unity_LightGammaCorrectionConsts_HalfDivPI * unity_LightGammaCorrectionConsts_8
                   * unity_LightGammaCorrectionConsts_SqrtHalfPI;
                return half4(c, 1);
            }
            ENDCG
        }
    }
}
