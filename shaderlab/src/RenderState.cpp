// SPDX-License-Identifier: Apache-2.0
// Inheritance of render state from an enclosing SubShader or Category.
#include "varc/shaderlab/RenderState.h"

namespace varc::shaderlab {
namespace {

void fill(StateValue& value, const StateValue& outer) {
    if (!value.isSet()) value = outer;
}

// Blend factors (or `Blend Off`) and BlendOp are written by separate commands, so each group
// inherits on its own. Example: a pass with only `BlendOp Max` under `Blend One One` blends
// One One with Max.
BlendState mergeBlend(const BlendState& inner, const BlendState& outer) {
    BlendState merged = inner;
    bool factorsWritten = inner.off || inner.src.isSet();
    if (!factorsWritten) {
        merged.off = outer.off;
        merged.src = outer.src;
        merged.dst = outer.dst;
        merged.srcAlpha = outer.srcAlpha;
        merged.dstAlpha = outer.dstAlpha;
    }
    if (!inner.op.isSet()) {
        merged.op = outer.op;
        merged.opAlpha = outer.opAlpha;
    }
    return merged;
}

StencilFace mergeFace(StencilFace face, const StencilFace& outer) {
    fill(face.comp, outer.comp);
    fill(face.pass, outer.pass);
    fill(face.fail, outer.fail);
    fill(face.zFail, outer.zFail);
    return face;
}

StencilState mergeStencil(StencilState inner, const StencilState& outer) {
    fill(inner.ref, outer.ref);
    fill(inner.readMask, outer.readMask);
    fill(inner.writeMask, outer.writeMask);
    inner.front = mergeFace(inner.front, outer.front);
    inner.back = mergeFace(inner.back, outer.back);
    return inner;
}

}  // namespace

RenderState RenderState::inheritedFrom(const RenderState& outer) const {
    RenderState merged = *this;
    if (!blend)
        merged.blend = outer.blend;
    else if (outer.blend)
        merged.blend = mergeBlend(*blend, *outer.blend);
    if (!stencil)
        merged.stencil = outer.stencil;
    else if (outer.stencil)
        merged.stencil = mergeStencil(*stencil, *outer.stencil);
    if (!offset) merged.offset = outer.offset;
    fill(merged.zWrite, outer.zWrite);
    fill(merged.zTest, outer.zTest);
    fill(merged.cull, outer.cull);
    fill(merged.colorMask, outer.colorMask);
    fill(merged.alphaToMask, outer.alphaToMask);
    fill(merged.conservative, outer.conservative);
    fill(merged.zClip, outer.zClip);
    return merged;
}

}  // namespace varc::shaderlab
