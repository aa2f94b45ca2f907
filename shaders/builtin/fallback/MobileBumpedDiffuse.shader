// SPDX-License-Identifier: Apache-2.0
// varc built-in: "Mobile/Bumped Diffuse" as a fallback. Its shadow caster is the one of its own fallback,
// Legacy Shaders/VertexLit, as in Unity. Written for varc.
Shader "Mobile/Bumped Diffuse" {
    Fallback "Legacy Shaders/VertexLit"
}
