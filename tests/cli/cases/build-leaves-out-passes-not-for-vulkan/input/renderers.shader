Shader "Test/Renderers" {
    SubShader {
        Pass {
            GLSLPROGRAM
            #pragma only_renderers gles3 gles
            #extension GL_OES_EGL_image_external_essl3 : enable
            #ifdef VERTEX
            void main() { gl_Position = vec4(0.0); }
            #endif
            #ifdef FRAGMENT
            uniform samplerExternalOES _MainTex;
            void main() { gl_FragColor = texture2D(_MainTex, vec2(0.5)); }
            #endif
            ENDGLSL
        }
        Pass {
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma exclude_renderers d3d9
            float4 vert(float4 p : POSITION) : SV_POSITION { return p; }
            float4 frag() : SV_Target { return 1; }
            ENDCG
        }
    }
}
