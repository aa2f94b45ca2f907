// SPDX-License-Identifier: Apache-2.0
// Fixed-function render state of a ShaderLab pass, as written (values may name properties).
#pragma once

#include <optional>
#include <string>

namespace varc::shaderlab {

// A state value that is either a literal ("One", "LEqual", "Off", "2") or a property reference
// written in brackets (`[_SrcBlend]`), resolved from material properties at runtime.
struct StateValue {
    std::string literal;   // as written, original case, when not a property reference
    std::string property;  // property name without brackets, when a reference

    bool isProperty() const { return !property.empty(); }
    bool isSet() const { return !literal.empty() || !property.empty(); }
    friend bool operator==(const StateValue&, const StateValue&) = default;
};

// `Blend Src Dst [, SrcA DstA]` or `Blend Off`.
struct BlendState {
    bool off = false;
    StateValue src, dst, srcAlpha, dstAlpha;  // alpha factors unset = same as color
    StateValue op, opAlpha;                   // from BlendOp
    friend bool operator==(const BlendState&, const BlendState&) = default;
};

// One face's stencil operations; `Comp`/`Pass`/... set both faces, `CompFront`/... one.
struct StencilFace {
    StateValue comp, pass, fail, zFail;
    friend bool operator==(const StencilFace&, const StencilFace&) = default;
};

struct StencilState {
    StateValue ref, readMask, writeMask;
    StencilFace front, back;
    friend bool operator==(const StencilState&, const StencilState&) = default;
};

// Unset fields inherit from the enclosing SubShader/Category, then use Unity's defaults
// (Blend Off, ZWrite On, ZTest LEqual, Cull Back, ColorMask RGBA, no Offset, no stencil).
struct RenderState {
    std::optional<BlendState> blend;
    StateValue zWrite, zTest, cull, colorMask;
    std::optional<std::pair<StateValue, StateValue>> offset;  // factor, units
    std::optional<StencilState> stencil;

    // Fields unset here take the value from |outer| (the enclosing scope).
    RenderState inheritedFrom(const RenderState& outer) const;
    friend bool operator==(const RenderState&, const RenderState&) = default;
};

}  // namespace varc::shaderlab
