// SPDX-License-Identifier: Apache-2.0
// varc built-in: the legacy alpha-blended VertexLit shader as a fallback. Alpha-blended legacy
// shaders cast no shadows in Unity's built-in pipeline: this one ends their fallback chain with
// no ShadowCaster pass, so a transparent shader that falls back to it casts none either.
// Written for varc.
Shader "Legacy Shaders/Transparent/VertexLit" {
    Properties {
        _Color ("Main Color", Color) = (1, 1, 1, 1)
        _MainTex ("Base (RGB) Trans (A)", 2D) = "white" {}
    }
}
