// Idioms of Unity-era post effects written for Direct3D 11 (compare
// SlightlyMad/VolumetricLights' BilateralBlur): separate textures and samplers through Unity's
// macros and by hand, texture parameters, an [unroll] loop whose variable outlives the loop
// (fxc scope), and Sample offsets that are constant only once the loop is unrolled.
Shader "Test/D3D11Blur" {
    Properties { _MainTex ("Texture", 2D) = "white" {} }
    SubShader { Pass {
        CGPROGRAM
        #pragma vertex vert_img
        #pragma fragment frag
        #include "UnityCG.cginc"
        UNITY_DECLARE_TEX2D(_MainTex);
        UNITY_DECLARE_TEX2D_NOSAMPLER(_Mask);
        Texture2D _Depth;
        SamplerState point_clamp_sampler;

        float4 blur(float2 uv, int2 direction, Texture2D depth, SamplerState depthSampler,
                    const int kernelRadius) {
            float4 color = 0;
            [unroll] for (int i = -kernelRadius; i < 0; i += 1) {
                float2 offset = direction * i;
                color += _MainTex.Sample(sampler_MainTex, uv, offset);
                color += depth.Sample(depthSampler, uv, offset).r;
            }
            [unroll] for (i = 1; i <= kernelRadius; i += 1) {
                color += _MainTex.Sample(sampler_MainTex, uv, direction * i);
            }
            return color / (2 * kernelRadius);
        }

        fixed4 frag(v2f_img input) : SV_Target {
            return blur(input.uv, int2(1, 0), _Depth, point_clamp_sampler, 3) *
                   UNITY_SAMPLE_TEX2D_SAMPLER(_Mask, _MainTex, input.uv);
        }
        ENDCG
    } }
}
