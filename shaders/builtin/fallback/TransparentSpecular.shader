// SPDX-License-Identifier: Apache-2.0
// varc built-in: "Legacy Shaders/Transparent/Specular" as a fallback: alpha blended, so it casts no shadows (its fallback,
// Legacy Shaders/Transparent/VertexLit, has no ShadowCaster pass), as in Unity. Written for varc.
Shader "Legacy Shaders/Transparent/Specular" {
    Fallback "Legacy Shaders/Transparent/VertexLit"
}
