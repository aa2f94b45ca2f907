// Evaluates one built-in helper per variant at every pixel of a full-target quad, so the tests
// can compare lavapipe's result with the CPU formula (tests/vulkan/BuiltinHelpersTest.cpp).
// Pixel (u, v) maps to the world position lerp(_BoxMin, _BoxMax, (u, v, _BoxZ)) and to a unit
// normal on the sphere (longitude u, latitude v).
Shader "Test/BuiltinHelpers" {
    SubShader {
        Pass {
            Tags { "LightMode" = "ForwardAdd" }
            Cull Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 3.0
            #pragma multi_compile_fwdadd
            #pragma multi_compile HELPER_ATTENUATION HELPER_SHADE4 HELPER_SH9 HELPER_BRDF
            #include "UnityPBSLighting.cginc"
            #include "AutoLight.cginc"

            float4 _BoxMin, _BoxMax;
            float _BoxZ;
            float4 _Albedo;       // rgb, a = metallic
            float _Smoothness;
            float4 _ViewDir;      // xyz, unit

            struct Interpolators {
                float4 pos : SV_POSITION;
                float2 uv : TEXCOORD0;
            };

            Interpolators vert(float4 vertex : POSITION, float2 uv : TEXCOORD0) {
                Interpolators i;
                i.pos = float4(vertex.xy, 0.5, 1.0);
                i.uv = uv;
                return i;
            }

            float3 worldPosition(float2 uv) { return lerp(_BoxMin.xyz, _BoxMax.xyz, float3(uv, _BoxZ)); }

            float3 sphereNormal(float2 uv) {
                float longitude = uv.x * 6.2831853;
                float latitude = (uv.y - 0.5) * 3.1415926;
                return float3(cos(latitude) * cos(longitude), sin(latitude), cos(latitude) * sin(longitude));
            }

            float4 frag(Interpolators i) : SV_Target {
                float3 worldPos = worldPosition(i.uv);
                float3 normal = sphereNormal(i.uv);
            #if defined(HELPER_ATTENUATION)
                UNITY_LIGHT_ATTENUATION(attenuation, i, worldPos);
                return float4(attenuation, i.uv, 1);  // uv keeps the interface used for DIRECTIONAL
            #elif defined(HELPER_SHADE4)
                float3 light = Shade4PointLights(unity_4LightPosX0, unity_4LightPosY0, unity_4LightPosZ0,
                                                 unity_LightColor[0].rgb, unity_LightColor[1].rgb,
                                                 unity_LightColor[2].rgb, unity_LightColor[3].rgb,
                                                 unity_4LightAtten0, worldPos, normal);
                return float4(light, 1);
            #elif defined(HELPER_SH9)
                return float4(ShadeSH9(float4(normal, 1)), 1);
            #else
                float3 specular;
                float oneMinusReflectivity;
                float3 diffuse = DiffuseAndSpecularFromMetallic(_Albedo.rgb, _Albedo.a, specular, oneMinusReflectivity);
                UnityLight light;
                light.color = _LightColor0.rgb;
                light.dir = normalize(_WorldSpaceLightPos0.xyz);
                light.ndotl = 0;
                UnityIndirect indirect;
                indirect.diffuse = 0;
                indirect.specular = 0;
                return UNITY_BRDF_PBS(diffuse, specular, oneMinusReflectivity, _Smoothness, normal, _ViewDir.xyz,
                                      light, indirect);
            #endif
            }
            ENDCG
        }
    }
}
