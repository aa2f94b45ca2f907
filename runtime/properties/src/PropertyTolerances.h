// SPDX-License-Identifier: Apache-2.0
// The tolerances of the property relations, derived in docs/PROPERTIES.md.
#pragma once

#include <cstddef>

namespace varc::properties {

// Half-float storage (RGBA16F) rounds to 11 significant bits: 2^-11 relative per stored value.
inline constexpr float kHalfUlp = 1.0f / 2048.0f;
// A value a correct shader leaves at zero, stored in RGBA16F: far below one 8-bit LSB (1/255).
inline constexpr float kZero = 1.0f / 4096.0f;
// A light beyond its range still adds the falloff table's last texel (~5.3e-5 x intensity 2 x a
// BRDF <= ~2): 5e-4 bounds it; a light left unattenuated adds ~0.1..1.
inline constexpr float kOutOfRange = 5.0e-4f;
// 8-bit target (RGBA8 UNORM, values stored as round(v x 255)): a sum of three rounded renders
// against one rounded render differs by up to 1.5 LSB; 2 LSB, saturated pixels skipped.
inline constexpr float kLsb = 1.0f / 255.0f;
// Scene moved or scaled: float32 vertex positions at |p| ~ 10 m shift rasterised edges (the 3x3
// window absorbs a pixel) and interior values by ~1e-5; 2^-8 relative + 2^-9 absolute leaves a
// margin over half-float storage and is far below the 50% of an unnormalised normal at scale 2.
inline constexpr float kMovedRelative = 1.0f / 256.0f;
inline constexpr float kMovedAbsolute = 1.0f / 512.0f;
// Forward against deferred: the G-buffer stores the colours as 8-bit sRGB and the smoothness in
// 8 bits. One sRGB LSB is <= 0.93% of a diffuse colour of 0.96, 3.4% of a specular colour of
// 0.04; half a smoothness LSB moves GGX's peak by ~3.2%: <= 0.93% x (1 - s) + 7% x s for a
// specular share s <= 14% (F0 0.04, smoothness 0.5) is <= 1.8% (docs/PROPERTIES.md; measured 0.5%).
inline constexpr float kGBufferRelative = 0.02f;
// The LDR light buffer holds q = 2^-c in 8 bits: half an LSB of q is 0.5 / (q ln 2) = 0.72 x 2^c
// LSB of the decoded c.
inline constexpr float kLdrDecodeLsb = 0.72f;

// The share of the pixels a key light must change (or a doubled light brighten) to count: 2%, as
// for `lit`, by more than 1/64 (4 8-bit LSB, far above half-float rounding of values <= 4).
inline constexpr size_t kSharePercent = 2;
inline constexpr float kVisible = 1.0f / 64.0f;

}  // namespace varc::properties
