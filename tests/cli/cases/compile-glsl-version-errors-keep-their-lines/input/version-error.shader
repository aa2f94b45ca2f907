// An error after a hoisted #version is reported at its own line and column.
Shader "Test/GlslVersionError" {
    SubShader {
        Pass {
            GLSLPROGRAM
            // A comment above the directive.
            #version 330
            #ifdef VERTEX
            void main() { gl_Position = vec4(0.0); }
            #endif
            #ifdef FRAGMENT
            out vec4 color; void main() { color = missing; }
            #endif
            ENDGLSL
        }
    }
}
