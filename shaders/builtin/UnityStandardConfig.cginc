// SPDX-License-Identifier: Apache-2.0
// varc built-in: UnityStandardConfig.cginc. Configuration switches of the Standard shader family.
// varc ships the full per-pixel path with the BRDF of UnityStandardBRDF.cginc and the simple forward
// path (UNITY_STANDARD_SIMPLE). Written for varc.
#ifndef UNITY_STANDARD_CONFIG_INCLUDED
#define UNITY_STANDARD_CONFIG_INCLUDED

// The full Standard path unless a shader defines UNITY_STANDARD_SIMPLE 1 before its includes
// (UnityStandardCoreForward.cginc then takes UnityStandardCoreForwardSimple.cginc).
#ifndef UNITY_STANDARD_SIMPLE
#define UNITY_STANDARD_SIMPLE 0
#endif
// GGX specular (the only BRDF varc has).
#ifndef UNITY_BRDF_GGX
#define UNITY_BRDF_GGX 1
#endif
// Detail normal maps are blended when _DETAIL_* is on.
#ifndef UNITY_ENABLE_DETAIL_NORMALMAP
#define UNITY_ENABLE_DETAIL_NORMALMAP 1
#endif
// The fragment program always receives the world position.
#ifndef UNITY_REQUIRE_FRAG_WORLDPOS
#define UNITY_REQUIRE_FRAG_WORLDPOS 1
#endif

// What varc's Standard code does, under Unity's switch names (issue #27): energy conservation
// by the specular colour's largest component (UnityStandardUtils.cginc), the tangent frame used
// as interpolated (not re-orthonormalised), six mip steps of reflection-probe roughness
// (UnityImageBasedLighting.cginc) and the ambient SH split between vertex and pixel.
#ifndef UNITY_CONSERVE_ENERGY
#define UNITY_CONSERVE_ENERGY 1
#endif
#ifndef UNITY_CONSERVE_ENERGY_MONOCHROME
#define UNITY_CONSERVE_ENERGY_MONOCHROME 1
#endif
#ifndef UNITY_TANGENT_ORTHONORMALIZE
#define UNITY_TANGENT_ORTHONORMALIZE 0
#endif
#ifndef UNITY_SPECCUBE_LOD_STEPS
#define UNITY_SPECCUBE_LOD_STEPS (6)
#endif
// Exponent of the roughness-to-mip mapping of an alternative probe filtering Unity documents
// (varc's perceptualRoughnessToMipmapLevel uses the r(1.7 - 0.7r) curve, not this one).
#ifndef UNITY_SPECCUBE_LOD_EXPONENT
#define UNITY_SPECCUBE_LOD_EXPONENT (1.5)
#endif
// The Standard passes save an interpolator by keeping the world position in the .w of the
// tangent frame rows, unless those hold the parallax view direction.
#ifndef UNITY_PACK_WORLDPOS_WITH_TANGENT
    #if UNITY_REQUIRE_FRAG_WORLDPOS && !defined(_PARALLAXMAP)
        #define UNITY_PACK_WORLDPOS_WITH_TANGENT 1
    #else
        #define UNITY_PACK_WORLDPOS_WITH_TANGENT 0
    #endif
#endif
#ifndef UNITY_SAMPLE_FULL_SH_PER_PIXEL
#define UNITY_SAMPLE_FULL_SH_PER_PIXEL 0
#endif

#endif // UNITY_STANDARD_CONFIG_INCLUDED
