// SPDX-License-Identifier: Apache-2.0
// Unity 5.6's one-argument UNITY_ACCESS_INSTANCED_PROP(name), given the 2017.3+ buffer argument.
#pragma once

#include <string>
#include <string_view>

namespace varc::frontend {

// |text| (HLSL before preprocessing) with each call `UNITY_ACCESS_INSTANCED_PROP(x)` that has
// one argument (no comma at the call's top level) rewritten to the two-argument form
// `UNITY_ACCESS_INSTANCED_PROP(UnityLegacyInstancedProps, x)`; two-argument calls, other names
// and text without such a call stay as written.
// Unity up to 2017.2 took the property alone (its per-instance block was implicit); 2017.3+
// takes the block's name first. glslang's preprocessor has no variadic macros, so one macro
// cannot take both: varc's UnityInstancing.cginc defines the two-argument form, whose
// expansion does not use the block name, and programs written for the old form are rewritten.
std::string expandLegacyInstancedPropAccess(std::string_view text);

}  // namespace varc::frontend
