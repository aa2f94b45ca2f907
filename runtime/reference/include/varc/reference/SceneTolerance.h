// SPDX-License-Identifier: Apache-2.0
// How close a GPU render of a scene must come to the CPU reference (docs/LIGHTING.md §9.2).
#pragma once

#include "varc/reference/ImageCompare.h"
#include "varc/scene/Scene.h"

namespace varc::reference {

// 1 LSB on interior and edge pixels; 2 LSB when a light samples a filtered texture (the falloff
// table of point and spot lights, any cookie), whose bilinear weights the GPU rounds to its own
// sub-texel precision; 6 LSB for deferred LDR scenes (the exp2/−log2 light-buffer encoding
// amplifies one buffer LSB up to ~3 LSB of the frame, and two of its roundings may differ). The
// mean signed error stays within ±0.25 LSB either way.
Tolerance toleranceFor(const scene::Scene& scene);

}  // namespace varc::reference
