// SPDX-License-Identifier: Apache-2.0
// varc built-in: "Mobile/VertexLit" as a fallback. Its shadow caster is the one of its own fallback,
// Legacy Shaders/VertexLit, as in Unity. Written for varc.
Shader "Mobile/VertexLit" {
    Fallback "Legacy Shaders/VertexLit"
}
