// SPDX-License-Identifier: Apache-2.0
// varc built-in: the tent-filter weight helpers of UnityShadowLibrary.cginc (included at its
// end), for programs that build their own PCF loops: how much of a triangle ("tent") filter
// falls on each texel of a row. Written for varc from the geometry the names state.
#ifndef VARC_SHADOW_TENT_WEIGHTS_INCLUDED
#define VARC_SHADOW_TENT_WEIGHTS_INCLUDED

// An isosceles right triangle of height h stands with its apex over the left edge of the first
// texel (the unit column [0, 1]): its height there falls from h to h - 1, so the area above that
// texel is the mean height, h - 0.5 (h >= 1).
float _UnityInternalGetAreaAboveFirstTexelUnderAIsocelesRectangleTriangle(float triangleHeight) {
    return triangleHeight - 0.5;
}

// A tent of half-width 1.5 (3 texels wide) centred at |offset| in [-0.5, 0.5] from the middle
// of a row of 4 texels (texel k spans [k - 2, k - 1], k = 0..3). computedAreaUncut: the area of
// the height-1.5 isosceles right triangle (total 2.25) over each texel; computedArea: those
// areas as fractions of the whole (sum 1). UnityShadowTentArea: UnityShadowLibrary.cginc.
void _UnityInternalGetAreaPerTexel_3TexelsWideTriangleFilter(float offset, out float4 computedArea, out float4 computedAreaUncut) {
    float4 left = float4(-2.0, -1.0, 0.0, 1.0) - offset;
    computedArea = float4(UnityShadowTentArea(left.y, 1.5), UnityShadowTentArea(left.z, 1.5),
                          UnityShadowTentArea(left.w, 1.5), 1.0)
                 - float4(UnityShadowTentArea(left.x, 1.5), UnityShadowTentArea(left.y, 1.5),
                          UnityShadowTentArea(left.z, 1.5), UnityShadowTentArea(left.w, 1.5));
    computedAreaUncut = computedArea * 2.25;
}

// The fractions of a 3-texel tent over its 4 texels (as computedArea above).
void _UnityInternalGetWeightPerTexel_3TexelsWideTriangleFilter(float offset, out float4 computedWeight) {
    float4 uncut;
    _UnityInternalGetAreaPerTexel_3TexelsWideTriangleFilter(offset, computedWeight, uncut);
}

// The fraction of a tent of half-width h centred at offset over the texel [k, k + 1].
float VarcTentTexelWeight(float k, float offset, float h) {
    return UnityShadowTentArea(k + 1.0 - offset, h) - UnityShadowTentArea(k - offset, h);
}

// A 5-texel tent (half-width 2.5) over 6 texels, k = -3..2: A = the first three, B the rest.
void _UnityInternalGetWeightPerTexel_5TexelsWideTriangleFilter(float offset, out float3 texelsWeightsA, out float3 texelsWeightsB) {
    texelsWeightsA = float3(VarcTentTexelWeight(-3.0, offset, 2.5), VarcTentTexelWeight(-2.0, offset, 2.5),
                            VarcTentTexelWeight(-1.0, offset, 2.5));
    texelsWeightsB = float3(VarcTentTexelWeight(0.0, offset, 2.5), VarcTentTexelWeight(1.0, offset, 2.5),
                            VarcTentTexelWeight(2.0, offset, 2.5));
}

// A 7-texel tent (half-width 3.5) over 8 texels, k = -4..3: A = the first four, B the rest.
void _UnityInternalGetWeightPerTexel_7TexelsWideTriangleFilter(float offset, out float4 texelsWeightsA, out float4 texelsWeightsB) {
    texelsWeightsA = float4(VarcTentTexelWeight(-4.0, offset, 3.5), VarcTentTexelWeight(-3.0, offset, 3.5),
                            VarcTentTexelWeight(-2.0, offset, 3.5), VarcTentTexelWeight(-1.0, offset, 3.5));
    texelsWeightsB = float4(VarcTentTexelWeight(0.0, offset, 3.5), VarcTentTexelWeight(1.0, offset, 3.5),
                            VarcTentTexelWeight(2.0, offset, 3.5), VarcTentTexelWeight(3.0, offset, 3.5));
}

#endif // VARC_SHADOW_TENT_WEIGHTS_INCLUDED
