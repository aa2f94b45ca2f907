// SPDX-License-Identifier: Apache-2.0
// Converts a ShaderLab pass's render state (as written) to the pack's typed render state.
#pragma once

#include <string>
#include <vector>

#include "varc/pack/PackRenderState.h"
#include "varc/shaderlab/RenderState.h"

namespace varc::driver {

struct ConvertedRenderState {
    pack::PackRenderState state;
    // One message per literal that could not be converted, naming the command and the value:
    // "ZTest: unknown comparison 'LEqaul' (expected Less, Greater, LEqual, ...)". The field keeps
    // Unity's default. The caller turns these into diagnostics at the pass's location.
    std::vector<std::string> errors;
    bool ok() const { return errors.empty(); }
};

// Literals are matched case-insensitively (`one`, `One`, `LEqual`, `off`); masks and the stencil
// reference are integers 0..255; Offset takes floats; `ColorMask` takes `0` or letters of RGBA.
// Property references (`[_SrcBlend]`) are kept by name beside Unity's default value. Unset
// fields get Unity's defaults; unset alpha blend factors and alpha BlendOp copy the color ones.
// Example: `Blend SrcAlpha OneMinusSrcAlpha` -> blendEnabled, srcColor = srcAlpha = SrcAlpha,
// dstColor = dstAlpha = OneMinusSrcAlpha.
ConvertedRenderState fromShaderLab(const shaderlab::RenderState& state);

}  // namespace varc::driver
