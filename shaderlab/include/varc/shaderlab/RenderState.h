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

// `Blend Src Dst [, SrcA DstA]` or `Blend Off` (render target 0; other targets are accepted and
// ignored). A scope that writes only `BlendOp` has a BlendState with `off == false` and unset
// factors: the factors then come from the enclosing scope, or mean "Blend Off" when none does.
struct BlendState {
    bool off = false;
    StateValue src, dst, srcAlpha, dstAlpha;  // alpha factors unset = same as color
    StateValue op, opAlpha;                   // from BlendOp; opAlpha unset = same as op
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
// (Blend Off, ZWrite On, ZTest LEqual, Cull Back, ColorMask RGBA, no Offset, no stencil,
// AlphaToMask Off, Conservative False, ZClip True).
struct RenderState {
    std::optional<BlendState> blend;
    StateValue zWrite, zTest, cull, colorMask;                // colorMask: render target 0 only
    std::optional<std::pair<StateValue, StateValue>> offset;  // factor, units
    std::optional<StencilState> stencil;
    StateValue alphaToMask, conservative, zClip;  // On/Off, True/False as written

    // Fields unset here take the value from |outer| (the enclosing scope). Blend factors and
    // BlendOp inherit separately (a pass may write only `BlendOp`); `Blend Off` written here
    // is kept. Stencil fields inherit one by one (a pass may override only `Ref`).
    // Example: {Cull Off}.inheritedFrom({Cull Front, ZWrite Off}) == {Cull Off, ZWrite Off}.
    RenderState inheritedFrom(const RenderState& outer) const;
    friend bool operator==(const RenderState&, const RenderState&) = default;
};

}  // namespace varc::shaderlab
