// SPDX-License-Identifier: Apache-2.0
// varc built-in: "Legacy Shaders/Transparent/Cutout/Specular" as a fallback. Its shadow caster (alpha tested against _Cutoff) is the
// one of its own fallback, Legacy Shaders/Transparent/Cutout/VertexLit, as in Unity.
// Written for varc.
Shader "Legacy Shaders/Transparent/Cutout/Specular" {
    Fallback "Legacy Shaders/Transparent/Cutout/VertexLit"
}
