// SPDX-License-Identifier: Apache-2.0
// How a resolved material draws into the CPU shadow maps.
#pragma once

#include "varc/reference/ReferenceRenderer.h"
#include "varc/reference/ShadowReference.h"

namespace varc::reference {

// How |m|'s object draws into the shadow maps.
ShadowCaster casterOf(const MaterialParams& m, const ReferenceOptions& options);

}  // namespace varc::reference
