// SPDX-License-Identifier: Apache-2.0
// Evaluates functions of UnityCG.glslinc, GLSLSupport.glslinc and UnityStereoSupport.glslinc at
// every pixel of a full-target quad (pixel centre (u, v) as input, four floats per variant) for
// tests/vulkan/TextCoreSimpleValueTest.cpp.
Shader "Test/GlslIncludeValues" {
    SubShader {
        Pass {
            Cull Off
            GLSLPROGRAM
            #pragma multi_compile API_GLSL_MISC API_GLSL_DIRECTIONS
            #include "GLSLSupport.glslinc"
            #include "UnityStereoSupport.glslinc"
            // Only what the fragment stage of the variant reads is passed on.
            #if !defined(API_GLSL_DIRECTIONS)
            varying vec2 uv;
            #endif
            varying vec4 directions;
            #ifdef VERTEX
            void main() {
                gl_Position = vec4(gl_Vertex.xy, 0.5, 1.0);
                vec4 p = vec4(gl_MultiTexCoord0.xy, 0.5, 1.0);
            #if !defined(API_GLSL_DIRECTIONS)
                uv = p.xy;
            #endif
            #if defined(API_GLSL_DIRECTIONS)
                // Linear in p, so the interpolated value is the function of the pixel's uv.
                directions = vec4(WorldSpaceViewDir(p).x, ObjSpaceViewDir(p).y, WorldSpaceLightDir(p).x, ObjSpaceLightDir(p).x);
            #else
                directions = (GetStereoMatrixVP(SetupStereoEyeIndex()) * p);
            #endif
            }
            #endif
            #ifdef FRAGMENT
            void main() {
            #if defined(API_GLSL_DIRECTIONS)
                gl_FragColor = directions;
            #else
                float u = uv.x, v = uv.y;
                gl_FragColor = vec4(saturate(3.0 * u - 1.0), ParallaxOffset(u, 0.2 + 0.5 * v, vec3(u - 0.5, v - 0.5, 0.3 + u)).x, directions.x, Luminance(vec3(u, v, 0.5)));
            #endif
            }
            #endif
            ENDGLSL
        }
    }
}
