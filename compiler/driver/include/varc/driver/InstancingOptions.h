// SPDX-License-Identifier: Apache-2.0
// The macros `#pragma instancing_options` switches define, as Unity's shader compiler does.
#pragma once

#include <string>
#include <vector>

#include "varc/driver/PredefinedMacro.h"

namespace varc::driver {

// One define per documented switch, in the order written (later ones win, as with #define):
//   procedural:FUNC     -> UNITY_INSTANCING_PROCEDURAL_FUNC FUNC (with the extra
//                          PROCEDURAL_INSTANCING_ON variant PragmaReader adds)
//   maxcount:N          -> UNITY_MAX_INSTANCE_COUNT N
//   forcemaxcount:N     -> UNITY_FORCE_MAX_INSTANCE_COUNT N
//   assumeuniformscaling-> UNITY_ASSUME_UNIFORM_SCALING 1
//   nomatrices          -> UNITY_DONT_INSTANCE_OBJECT_MATRICES 1
//   lodfade             -> UNITY_INSTANCED_LOD_FADE 1
//   renderinglayer      -> UNITY_INSTANCED_RENDERING_LAYER 1
// nolodfade, nolightprobe and nolightmap define nothing: varc never instances LOD fade, light
// probes or lightmap scale/offsets unless asked (its runtime batches only draws sharing them;
// UnityInstancing.cginc). Unknown switches, and a switch whose value is not a name or a count,
// define nothing. Example: {"procedural:setup", "maxcount:50"} ->
// {UNITY_INSTANCING_PROCEDURAL_FUNC setup, UNITY_MAX_INSTANCE_COUNT 50}.
std::vector<PredefinedMacro> instancingOptionMacros(const std::vector<std::string>& options);

}  // namespace varc::driver
