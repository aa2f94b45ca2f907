// Unity's enumeration order: the first declared set varies slowest.
Shader "Test/Order" {
    SubShader {
        Pass {
            Name "FORWARD"
            Tags { "LightMode" = "ForwardBase" }
            CGPROGRAM
            #pragma vertex vert
            #pragma fragment frag
            #pragma multi_compile _ SHADOWS_SCREEN
            #pragma multi_compile _ VERTEXLIGHT_ON
            #pragma shader_feature _METALLIC_MAP
            #pragma skip_variants NOT_DECLARED
            ENDCG
        }
    }
}
