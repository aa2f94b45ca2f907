// SPDX-License-Identifier: Apache-2.0
// Writes the fragment program of a generated surface pass.
#pragma once

#include "CodeWriter.h"
#include "PassPlan.h"

namespace varc::frontend::surface {

// `varc_surf_frag(varc_surf_v2f i) : SV_Target`: for the caster without a surface call the
// depth-only SHADOW_CASTER_FRAGMENT; otherwise Input from the varyings, the surface function,
// then SHADOW_CASTER_FRAGMENT (caster) or the lit colour (forward passes).
void writeFragmentProgram(const PassPlan& plan, CodeWriter& out);

}  // namespace varc::frontend::surface
