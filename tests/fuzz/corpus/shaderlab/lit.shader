Shader "Fuzz/Lit" {
    Properties { _Color ("Colour", Color) = (1, 0.5, 0.25, 1) _MainTex ("Texture", 2D) = "white" {} }
    SubShader {
        Tags { "RenderType" = "Opaque" }
        Pass {
            Tags { "LightMode" = "ForwardAdd" }
            Blend One One ZWrite Off Cull Back
            Stencil { Ref 2 Comp Equal Pass Keep }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile_fwdadd
            ENDCG
        }
    }
    Fallback "Diffuse"
}
