// SPDX-License-Identifier: Apache-2.0
// GLSLPROGRAM shaders on GLSLSupport.glslinc, UnityCG.glslinc and the stereo includes, written
// the way Unity's GLSL examples are: one program text split by #ifdef VERTEX / #ifdef FRAGMENT,
// legacy built-ins (gl_Vertex, gl_ModelViewProjectionMatrix, gl_NormalMatrix, gl_MultiTexCoord0).
// builtin.textcore-glsl builds every variant. Written for varc's tests.
Shader "varc-tests/GlslIncludes" {
    Properties {
        _MainTex ("Texture", 2D) = "white" {}
        _Height ("Parallax height", Float) = 0.02
    }

    SubShader {
        Pass {
            Tags { "LightMode" = "ForwardBase" }
            GLSLPROGRAM
            #pragma multi_compile __ STEREO_INSTANCING_ON
            #pragma multi_compile DIRECTIONAL POINT
            #include "GLSLSupport.glslinc"
            #include "UnityStereoExtensions.glslinc"
            #include "UnityStereoSupport.glslinc"
            #include "UnityCG.glslinc"

            uniform sampler2D _MainTex;
            uniform vec4 _MainTex_ST;
            uniform float _Height;

            varying vec2 uv;
            varying vec3 normalDir;
            varying vec3 viewDir;
            varying float lightTerm;

            #ifdef VERTEX
            attribute vec4 Tangent;
            void main() {
                int eye = SetupStereoEyeIndex();
                vec4 world = unity_ObjectToWorld * gl_Vertex;
                gl_Position = GetStereoMatrixVP(eye) * world + 0.0 * (gl_ModelViewProjectionMatrix * gl_Vertex);
                uv = TRANSFORM_TEX(gl_MultiTexCoord0, _MainTex) + TRANSFORM_UV(0) * 0.0;
                TANGENT_SPACE_ROTATION;
                normalDir = normalize(gl_NormalMatrix * gl_Normal) + rotation * ObjSpaceViewDir(gl_Vertex) * 0.0;
                viewDir = normalize(WorldSpaceViewDir(gl_Vertex));
            #ifdef USING_DIRECTIONAL_LIGHT
                lightTerm = saturate(dot(normalize(WorldSpaceLightDir(gl_Vertex)), normalDir));
            #else
                lightTerm = saturate(length(ObjSpaceLightDir(gl_Vertex)) * _LightPositionRange.w);
            #endif
            }
            #endif

            #ifdef FRAGMENT
            void main() {
                vec2 offset = ParallaxOffset(texture2D(_MainTex, uv).a, _Height, viewDir);
                vec4 c = texture2D(_MainTex, uv + offset);
                gl_FragColor = vec4(c.rgb * (lightTerm + Luminance(c.rgb)), c.a);
            }
            #endif
            ENDGLSL
        }

        Pass {
            Tags { "LightMode" = "ForwardAdd" }
            Blend One One
            GLSLPROGRAM
            #include "UnityCG.glslinc"
            #include "GLSLSupport.glslinc"
            varying vec3 normalDir;
            #ifdef VERTEX
            void main() {
                gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;
                normalDir = (transpose(gl_ModelViewMatrixInverseTranspose) * vec4(gl_Normal, 0.0)).xyz
                          + (gl_ModelViewMatrixTranspose * vec4(0.0)).xyz + (gl_ProjectionMatrix * gl_ModelViewMatrix)[0].xyz * 0.0;
            }
            #endif
            #ifdef FRAGMENT
            void main() {
                gl_FragColor = vec4(saturate(normalDir.z));
            }
            #endif
            ENDGLSL
        }
    }
}
