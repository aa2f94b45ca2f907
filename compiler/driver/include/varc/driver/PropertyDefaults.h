// SPDX-License-Identifier: Apache-2.0
// A ShaderLab property's default value as the pack stores it (pack::ShaderProperty), read from
// the text the parser kept: `0.5` for Float/Range/Int, `(1, 0.5, 0, 1)` for Color/Vector,
// `"white" {}` for textures.
#pragma once

#include <string>

#include "varc/core/Result.h"
#include "varc/pack/PackModel.h"
#include "varc/shaderlab/ShaderAst.h"

namespace varc::driver {

// The pack form of |property|. Errors (InvalidInput) say what the default should look like, e.g.
// for a Color written `1`: "the default of _Color (Color) should be (x, y, z, w), not '1'".
// Vectors of 2 or 3 numbers are padded with 0 (Unity pads the same way).
Result<pack::ShaderProperty> toPackProperty(const shaderlab::Property& property);

}  // namespace varc::driver
