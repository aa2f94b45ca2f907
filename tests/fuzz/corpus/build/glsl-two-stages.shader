Shader "FuzzBuild/Glsl" { SubShader { Pass { GLSLPROGRAM
uniform vec4 _Color;
#ifdef VERTEX
varying vec2 uv;
void main() { uv = gl_MultiTexCoord0.xy; gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex; }
#endif
#ifdef FRAGMENT
varying vec2 uv;
void main() { gl_FragColor = _Color * vec4(uv, 0.0, 1.0); }
#endif
ENDGLSL } } }
