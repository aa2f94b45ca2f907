// GLSLPROGRAMs whose #version follows comments: Unity's users write them so; glslang accepts
// nothing before #version. The ES one is compiled as 3.10 ES, the first ES SPIR-V takes.
Shader "Test/GlslVersion" {
    SubShader {
        Pass {
            GLSLPROGRAM
            // A comment above the directive.
            #version 330
            #ifdef VERTEX
            in vec4 position;
            void main() { gl_Position = position; }
            #endif
            #ifdef FRAGMENT
            out vec4 color;
            void main() { color = vec4(1.0); }
            #endif
            ENDGLSL
        }
        Pass {
            GLSLPROGRAM
            /* A block comment. */
            #version 300 es
            #ifdef VERTEX
            in vec4 position;
            void main() { gl_Position = position; }
            #endif
            #ifdef FRAGMENT
            precision mediump float;
            out vec4 color;
            void main() { color = vec4(0.5); }
            #endif
            ENDGLSL
        }
    }
}
