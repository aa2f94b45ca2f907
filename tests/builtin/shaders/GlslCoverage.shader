// SPDX-License-Identifier: Apache-2.0
// Test shader for tests/builtin (compile_fixtures.sh): a GLSLPROGRAM using UnityCG.glslinc,
// UnityLighting.glslinc and legacy built-ins (gl_Vertex, gl_ModelViewProjectionMatrix, ...).
Shader "varc-test/GlslCoverage" {
    SubShader {
        Pass {
            Tags { "LightMode" = "ForwardBase" }
            GLSLPROGRAM
            #pragma multi_compile_fwdbase
            #include "UnityCG.glslinc"
            #include "UnityLighting.glslinc"
            uniform vec4 _Color;
            uniform vec4 _MainTex_ST;
            uniform sampler2D _MainTex;
            varying vec4 worldPos;
            varying vec3 worldNormal;
            varying vec2 uv;
            varying vec3 vertexLight;
            #ifdef VERTEX
            void main() {
                worldPos = _Object2World * gl_Vertex;
                worldNormal = UnityObjectToWorldNormal(gl_Normal);
                uv = TRANSFORM_TEX(gl_MultiTexCoord0, _MainTex);
                vertexLight = vec3(0.0);
                #ifdef VERTEXLIGHT_ON
                vertexLight = Shade4PointLights(unity_4LightPosX0, unity_4LightPosY0, unity_4LightPosZ0,
                    unity_LightColor[0].rgb, unity_LightColor[1].rgb, unity_LightColor[2].rgb,
                    unity_LightColor[3].rgb, unity_4LightAtten0, worldPos.xyz, worldNormal);
                #endif
                gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex + 0.0 * UnityObjectToClipPos(gl_Vertex.xyz);
            }
            #endif
            #ifdef FRAGMENT
            void main() {
                vec3 n = normalize(worldNormal);
                vec3 l = normalize(WorldSpaceLightDir(vec4(0.0, 0.0, 0.0, 1.0)) + _WorldSpaceLightPos0.xyz);
                vec3 albedo = texture(_MainTex, uv).rgb * _Color.rgb;
                vec3 c = albedo * (_LightColor0.rgb * max(0.0, dot(n, l)) + ShadeSH9(vec4(n, 1.0))
                         + gl_LightModel.ambient.rgb + UNITY_LIGHTMODEL_AMBIENT.rgb + vertexLight);
                gl_FragColor = vec4(c, 1.0);
            }
            #endif
            ENDGLSL
        }
    }
}
