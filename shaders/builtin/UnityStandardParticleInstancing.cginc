// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityStandardParticleInstancing.cginc. The hooks particle shaders call for
// particles drawn with procedural instancing (per-particle colour, transform and flipbook frame).
// varc's renderer draws particles as ordinary meshes, so UNITY_PARTICLE_INSTANCING_ENABLED stays
// undefined and shaders take their non-instanced path; the hooks exist, as identities, for code
// that calls them unconditionally. Written for varc from Unity's documented behaviour.
#ifndef UNITY_STANDARD_PARTICLE_INSTANCING_INCLUDED
#define UNITY_STANDARD_PARTICLE_INSTANCING_INCLUDED

// `#pragma instancing_options procedural:vertInstancingSetup` names this function.
void vertInstancingSetup() {}

// The mesh colour stays the particle's colour.
void vertInstancingColor(inout half4 color) {}

// The mesh uv stays the particle's uv; the flipbook's second frame is the same, blend 0.
void vertInstancingUVs(float2 originalUV, out float2 uv) { uv = originalUV; }
void vertInstancingUVs(float2 originalUV, out float2 uv, out float3 uv2AndBlend) {
    uv = originalUV;
    uv2AndBlend = float3(originalUV, 0);
}

#endif // UNITY_STANDARD_PARTICLE_INSTANCING_INCLUDED
