// SPDX-License-Identifier: Apache-2.0
// The keywords a renderer turns on by itself, besides a light's (LightKeywords.h): one spelling
// of each for the whole code base (docs/KEYWORDS.md, "Light → keywords").
#pragma once

namespace varc::variants {

// The camera renders to a floating-point target: deferred G-buffer and light passes select
// their HDR variant with it.
inline constexpr const char* kHdrKeyword = "UNITY_HDR_ON";

// The draw is an instanced batch (one draw, per-instance properties in arrays).
inline constexpr const char* kInstancingKeyword = "INSTANCING_ON";

}  // namespace varc::variants
