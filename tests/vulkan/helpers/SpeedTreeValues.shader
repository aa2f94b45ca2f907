// SPDX-License-Identifier: Apache-2.0
// Evaluates varc's SpeedTree include functions (shaders/builtin/SpeedTree*.cginc) at every pixel
// of a full-target quad, one group per variant, so that tests/vulkan/SpeedTree*ValueTest.cpp can
// compare lavapipe's result with the documented formula or property computed on the CPU. Pixel
// centre (u, v) in (0, 1)^2 is the input; each variant writes four floats.
Shader "Test/SpeedTreeValues" {
    SubShader {
        Pass {
            Cull Off
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma target 3.0
            #pragma multi_compile ST_WAVES ST_UNPACK ST_ROTATE ST_COMPOSE ST_ROLL_TWITCH ST_OSCILLATE ST_BRANCH ST_GLOBAL ST_GLOBAL_SHAPE ST_LEAF ST_FROND ST_TUMBLE ST_FROND2 ST_PALM ST_LEAFWIND ST7_LEAF ST7_FROND ST7_BRANCH ST8_TREE ST7_SURFACE ST_BILLBOARD ST_BILLBOARD_FRAME ST_BILLBOARD_CAMPOS
            #if defined(ST7_LEAF) || defined(ST7_FROND) || defined(ST7_BRANCH) || defined(ST8_TREE)
                #define LOD_FADE_PERCENTAGE
            #endif
            #if defined(ST7_LEAF)
                #define GEOM_TYPE_LEAF
            #elif defined(ST7_FROND)
                #define GEOM_TYPE_FROND
            #elif defined(ST7_BRANCH)
                #define GEOM_TYPE_BRANCH
            #elif defined(ST7_SURFACE)
                #define GEOM_TYPE_BRANCH
                #define EFFECT_HUE_VARIATION
            #elif defined(ST_BILLBOARD_CAMPOS)
                #define BILLBOARD_FACE_CAMERA_POS
            #endif
            #if defined(ST8_TREE)
                #define ENABLE_WIND
                #define _WINDQUALITY_PALM
                #include "SpeedTree8Common.cginc"
            #elif defined(ST7_LEAF) || defined(ST7_FROND) || defined(ST7_BRANCH) || defined(ST7_SURFACE) || defined(ST_BILLBOARD) || defined(ST_BILLBOARD_FRAME) || defined(ST_BILLBOARD_CAMPOS)
                #define ENABLE_WIND
                #include "SpeedTreeBillboardCommon.cginc"
            #else
                #include "UnityCG.cginc"
                #include "SpeedTreeWind.cginc"
            #endif

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

            // The inputs every group shares (the test computes the same from u and v).
            static float3 stPos(float u, float v) { return float3(4.0 * u - 2.0, 8.0 * v, 2.0 * u * v - 0.5); }
            static const float3 stWind = float3(0.9, 0.0, 1.2);
            static const float3 stInstance = float3(3.0, 0.0, -7.0);
            float _StLod;  // the tree groups' LOD value (the test sets it; 0 otherwise)

            float4 frag(Interpolators i) : SV_Target {
                float u = i.uv.x, v = i.uv.y;
                float3 p = stPos(u, v);
            #if defined(ST_WAVES)
                return float4(TrigApproximate(float4(3.0 * u - 1.0, 0, 0, 0)).x, TriangleWave(float4(2.5 * v, 0, 0, 0)).x,
                              CubicSmooth(float4(v, 0, 0, 0)).x, TrigApproximate(float4(0, 0, 0, 4.0 * u * v)).w);
            #elif defined(ST_UNPACK)
                return float4(UnpackNormalFromFloat(15.99 * u), 0.0);
            #elif defined(ST_ROTATE) || defined(ST_COMPOSE)
                float3 axis = normalize(float3(u - 0.5, 1.0, v - 0.5));
                float3 vec = float3(1.0, 2.0 * v, -0.5);
            #if defined(ST_ROTATE)
                return float4(mul_float3x3_float3(RotationMatrix(axis, 6.0 * u - 3.0), vec), wind_cross(vec, axis).x);
            #else
                float3x3 both = mul_float3x3_float3x3(RotationMatrix(axis, 2.0 * v), RotationMatrix(axis, 1.0 - u));
                return float4(mul_float3x3_float3(both, vec), wind_cross(vec, axis).z);
            #endif
            #elif defined(ST_ROLL_TWITCH)
                return float4(Roll(1.3, 1.2, 0.4, 0.8, 0.3, p, 5.0 * v, stWind), Twitch(p, 0.9, v, 3.0 * u),
                              Turbulence(2.0 * u, v, 7.0 * v, 0.6), 0.0);
            #elif defined(ST_OSCILLATE)
                float4 waves = 0, plainWaves = 0;
                float full = Oscillate(p, 3.0 * u, v, 0.7, 0.5, true, true, true, 0.4, 1.7, waves, stWind);
                float plain = Oscillate(p, 3.0 * u, v, 0.7, 0.5, false, false, false, 0.4, 1.7, plainWaves, stWind);
                return float4(full, waves.y, waves.w, plain);
            #elif defined(ST_BRANCH)
                float3 simple = SimpleBranchWind(p, stInstance, v, u, 2.3, 0.8, 0.3, 1.9, 0.4, true, false, true, stWind);
                float3 directional = DirectionalBranchWind(p, stInstance, v, u, 2.3, 0.8, 0.5, 0.35, 0.3, 1.9, 0.4,
                                                          true, false, true, true, stWind);
                return float4(simple, directional.z);
            #elif defined(ST_GLOBAL)
                float3 bent = GlobalWind(p, stInstance, false, stWind, 1.7 * u);
                return float4(bent, length(GlobalWind(p, stInstance, true, stWind, 1.7 * u)));
            #elif defined(ST_GLOBAL_SHAPE)
                return float4(GlobalWind(p, stInstance, true, stWind, 1.7 * u), 0.0);
            #elif defined(ST_LEAF)
                float3 normal = float3(0.0, 1.0, 0.0);
                float3 rippled = LeafRipple(p, normal, 0.8, 7.3 + u, 2.0 * v, 0.5, true, u);
                return float4(rippled, LeafRipple(p, normal, 0.8, 7.3 + u, 2.0 * v, 0.5, false, u).y);
            #elif defined(ST_FROND)
                float3 normal = float3(0.0, 0.0, 1.0);
                float3 rippled = RippleFrondOneSided(p, normal, u, v, 0.7, float3(1.0, 0.0, 0.0), float3(0.0, 1.0, 0.0));
                return float4(rippled, normal.x);
            #elif defined(ST_FROND2)
                float3 normal = float3(0.0, 0.0, 1.0);
                float3 rippled = RippleFrond(p, normal, u, v, 7.3 + u, 0.7, v, float3(1.0, 0.0, 0.0), float3(0.0, 1.0, 0.0));
                return float4(rippled, normal.y);
            #elif defined(ST_PALM)
                float3 anchor = float3(0.0, 0.5, 0.0);
                float3 palm = BranchWind(true, p, stInstance, float4(v, u, 0.0, 0.0), stWind, anchor);
                return float4(palm, BranchWind(false, p, stInstance, float4(v, u, 0.0, 0.0), stWind, anchor).x);
            #elif defined(ST_LEAFWIND)
                float3 normal = normalize(float3(u, 1.0, v));
                float3 anchor = p + float3(0.3, -0.2, 0.1);
                float3 rippled = LeafWind(false, false, p, normal, 0.8, anchor, 9.1 + v, 7.3 + u, u, stWind);
                float3 tumbled = LeafWind(true, true, p, normal, 0.8, anchor, 9.1 + v, 7.3 + u, u, stWind);
                return float4(rippled, length(tumbled - anchor));
            #elif defined(ST_TUMBLE)
                float3 normal = normalize(float3(u, 1.0, v));
                float3 anchor = p + float3(0.3, -0.2, 0.1);
                float3 turned = LeafTumble(p, normal, 0.9, anchor, float3(0.0, 1.0, 0.2), u, 4.0 * v, 0.8, 0.6, 0.3,
                                           float3(0.4, 0.5, v), float4(1.2, 0.5, 0.7, 0.2), true, true, stWind);
                return float4(length(turned - anchor), length(normal), dot(turned - anchor, normal), length(turned - p));
            #elif defined(ST7_LEAF) || defined(ST7_FROND) || defined(ST7_BRANCH)
                SpeedTreeVB data = (SpeedTreeVB)0;
                data.vertex = float4(p, 1.0);
                data.normal = normalize(float3(u, 1.0, v));
                data.tangent = float4(1.0, 0.0, 0.0, 1.0);
                data.texcoord = float4(u, v, v, 3.0 * u);
                data.texcoord1 = float4(p + float3(0.1, 0.2, 0.3), 0.7);
                data.texcoord2 = float4(p + float3(0.3, -0.2, 0.1), 7.3 + u);
                data.texcoord3 = float2(3.7 + v, u > 0.5 ? 1.0 : 0.0);
                float3 before = data.normal;
                OffsetSpeedTreeVertex(data, _StLod);
                return float4(data.vertex.xyz, length(data.normal - before));
            #elif defined(ST7_SURFACE)
                SpeedTreeVB data = (SpeedTreeVB)0;
                data.vertex = float4(p, 1.0);
                data.texcoord = float4(u, v, 0.0, 0.0);
                data.color = half4(u, 1.0, 1.0, 1.0);
                Input input;
                SpeedTreeVert(data, input);
                SpeedTreeFragOut fragment;
                SpeedTreeFrag(input, fragment);
                struct { fixed3 Albedo; fixed Alpha; } surface;
                SPEEDTREE_COPY_FRAG(surface, fragment)
                return float4(surface.Albedo, surface.Alpha + input.mainTexUV.x + input.mainTexUV.y);
            #elif defined(ST8_TREE)
                appdata_full data = (appdata_full)0;
                data.vertex = float4(p, 1.0);
                data.normal = normalize(float3(u, 1.0, v));
                data.tangent = float4(1.0, 0.0, 0.0, 1.0);
                data.texcoord = float4(u, v, v, 3.0 * u);
                data.texcoord1 = float4(p + float3(0.1, 0.2, 0.3), 0.7);
                data.texcoord2 = float4(p + float3(0.3, -0.2, 0.1), 7.3 + u);
                data.texcoord3 = float4(3.7 + v, u > 0.5 ? 1.0 : 0.0, 0.0, floor(3.0 * v));
                float3 before = data.normal;
                OffsetSpeedTreeVertex(data, _StLod);
                return float4(data.vertex.xyz, length(data.normal - before));
            #else
                SpeedTreeBillboardData data = (SpeedTreeBillboardData)0;
                data.vertex = float4(10.0 * u - 5.0, 0.0, 10.0 * v - 5.0, 1.0);
                data.texcoord = frac(float2(4.0 * u, 4.0 * v));
                data.texcoord1 = float4(0.7, 1.5, 0.0, 0.0);
                Input result;
                SpeedTreeBillboardVert(data, result);
            #if defined(ST_BILLBOARD_FRAME)
                return float4(data.normal.x, data.normal.z, data.tangent.z, result.mainTexUV.y);
            #else
                return float4(data.vertex.xyz, result.mainTexUV.x);
            #endif
            #endif
            }
            ENDCG
        }
    }
}
