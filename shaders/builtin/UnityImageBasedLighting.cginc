// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityImageBasedLighting.cginc. Glossy environment lookups in reflection-probe
// cube maps: roughness -> mip level, the HDR decode, and the setup struct the GI code passes
// around. Probe textures and parameters: UnityShaderVariables.cginc, docs/SHADER_ABI.md §4.13.
// Written for varc from the documented behaviour; not derived from Unity's file.
#ifndef UNITY_IMAGE_BASED_LIGHTING_INCLUDED
#define UNITY_IMAGE_BASED_LIGHTING_INCLUDED

#include "UnityCG.cginc"
#include "UnityStandardBRDF.cginc"

// Mip levels of a probe cube map spanned by perceptual roughness 0..1 (mip 0 = mirror).
#ifndef UNITY_SPECCUBE_LOD_STEPS
#define UNITY_SPECCUBE_LOD_STEPS (6)
#endif

// Sampling helpers for importance-sampled reference integrals (issue #27): the bit-reversed
// radical inverse (van der Corput sequence), the Hammersley point i of n, and an orthonormal
// frame (tangentX, tangentY, N) around a unit normal.
uint ReverseBits32(uint bits) { return reversebits(bits); }
float RadicalInverse_VdC(uint bits) { return float(ReverseBits32(bits)) * 2.3283064365386963e-10; } // / 2^32
float2 Hammersley2d(uint i, uint maxSampleCount) {
    return float2(float(i) / float(maxSampleCount), RadicalInverse_VdC(i));
}
void GetLocalFrame(float3 N, out float3 tangentX, out float3 tangentY) {
    float3 up = abs(N.z) < 0.999 ? float3(0, 0, 1) : float3(1, 0, 0);
    tangentX = normalize(cross(up, N));
    tangentY = cross(N, tangentX);
}

struct Unity_GlossyEnvironmentData {
    half roughness;   // perceptual roughness (1 - smoothness)
    half3 reflUVW;    // lookup direction (reflected view vector, world space)
};

Unity_GlossyEnvironmentData UnityGlossyEnvironmentSetup(half Smoothness, half3 worldViewDir, half3 Normal, half3 fresnel0) {
    Unity_GlossyEnvironmentData g;
    g.roughness = 1.0 - Smoothness;
    g.reflUVW = reflect(-worldViewDir, Normal);
    return g;
}

// Linear mapping of perceptual roughness to the probe's mip chain.
half perceptualRoughnessToMipmapLevel(half perceptualRoughness) {
    return perceptualRoughness * UNITY_SPECCUBE_LOD_STEPS;
}
// Inverse of the mip mapping, for shaders that go the other way.
half mipmapLevelToPerceptualRoughness(half mipmapLevel) {
    return mipmapLevel / UNITY_SPECCUBE_LOD_STEPS;
}

// Pre-filtered radiance from a probe: the roughness is bent by r * (1.7 - 0.7 r) so that the
// linear mip chain better follows the GGX lobe width, then the mip is sampled and decoded.
half3 Unity_GlossyEnvironment(UNITY_ARGS_TEXCUBE(tex), half4 hdr, Unity_GlossyEnvironmentData glossIn) {
    half perceptualRoughness = glossIn.roughness * (1.7 - 0.7 * glossIn.roughness);
    half mip = perceptualRoughnessToMipmapLevel(perceptualRoughness);
    half4 rgbm = UNITY_SAMPLE_TEXCUBE_LOD(tex, glossIn.reflUVW, mip);
    return DecodeHDR(rgbm, hdr);
}

// The 5.x Unity_GlossyEnvironment overload (UnityDeprecated.cginc).
#define INCLUDE_UNITY_IMAGE_BASED_LIGHTING_DEPRECATED
#include "UnityDeprecated.cginc"
#undef INCLUDE_UNITY_IMAGE_BASED_LIGHTING_DEPRECATED

// Reference integrals (importance sampling, DFG, pre-filtered radiance, diffuse/specular IBL).
#include "VarcIblReference.cginc"

#endif // UNITY_IMAGE_BASED_LIGHTING_INCLUDED
