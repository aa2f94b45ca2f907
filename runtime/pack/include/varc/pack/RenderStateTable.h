// SPDX-License-Identifier: Apache-2.0
// The RenderStates record: slot numbering, schema, and a visitor shared by writer and reader.
#pragma once

#include <array>
#include <cstdint>
#include <type_traits>

#include "varc/pack/LittleEndian.h"
#include "varc/pack/PackRenderState.h"
#include "varc/pack/TableSchema.h"

namespace varc::pack {

// A RenderStates record is [blendEnabled, stencilEnabled] followed, for every slot below, by
// the slot's value (enum value, mask, or float bits) and its property name (a String; "" for a
// literal). Example: `Blend [_SrcBlend] Zero` stores SrcColor = {One, "_SrcBlend"} and
// DstColor = {Zero, ""}.
enum RenderStateSlot : uint32_t {
    kRsSrcColor,
    kRsDstColor,
    kRsSrcAlpha,
    kRsDstAlpha,
    kRsColorOp,
    kRsAlphaOp,
    kRsZWrite,
    kRsZTest,
    kRsCull,
    kRsColorMask,
    kRsOffsetFactor,
    kRsOffsetUnits,
    kRsStencilRef,
    kRsStencilReadMask,
    kRsStencilWriteMask,
    kRsFrontComp,
    kRsFrontPass,
    kRsFrontFail,
    kRsFrontZFail,
    kRsBackComp,
    kRsBackPass,
    kRsBackFail,
    kRsBackZFail,
    kRsSlotCount
};
inline constexpr uint32_t kRsBlendEnabled = 0;
inline constexpr uint32_t kRsStencilEnabled = 1;
inline constexpr uint32_t kRenderStateFieldCount = 2 + 2 * kRsSlotCount;

constexpr uint32_t renderStateValueField(uint32_t slot) { return 2 + 2 * slot; }
constexpr uint32_t renderStatePropertyField(uint32_t slot) { return 3 + 2 * slot; }

// Calls |visit(slot, field)| for every StateField of |state| in slot order. |State| may be
// const or not; |field| is a StateField<T> with T varying per slot.
template <typename State, typename Visit>
void forEachStateField(State& state, Visit&& visit) {
    visit(kRsSrcColor, state.srcColor);
    visit(kRsDstColor, state.dstColor);
    visit(kRsSrcAlpha, state.srcAlpha);
    visit(kRsDstAlpha, state.dstAlpha);
    visit(kRsColorOp, state.colorOp);
    visit(kRsAlphaOp, state.alphaOp);
    visit(kRsZWrite, state.zWrite);
    visit(kRsZTest, state.zTest);
    visit(kRsCull, state.cull);
    visit(kRsColorMask, state.colorMask);
    visit(kRsOffsetFactor, state.offsetFactor);
    visit(kRsOffsetUnits, state.offsetUnits);
    visit(kRsStencilRef, state.stencilRef);
    visit(kRsStencilReadMask, state.stencilReadMask);
    visit(kRsStencilWriteMask, state.stencilWriteMask);
    visit(kRsFrontComp, state.front.comp);
    visit(kRsFrontPass, state.front.pass);
    visit(kRsFrontFail, state.front.fail);
    visit(kRsFrontZFail, state.front.zFail);
    visit(kRsBackComp, state.back.comp);
    visit(kRsBackPass, state.back.pass);
    visit(kRsBackFail, state.back.fail);
    visit(kRsBackZFail, state.back.zFail);
}

// The stored bits of a state value.
template <typename T>
constexpr uint32_t stateValueBits(T value) {
    if constexpr (std::is_same_v<T, float>) {
        return floatBits(value);
    } else if constexpr (std::is_enum_v<T>) {
        return static_cast<uint32_t>(value);
    } else {
        return static_cast<uint32_t>(value);  // bool, uint8_t
    }
}

// The inverse of stateValueBits; |bits| has passed the schema's range check.
template <typename T>
constexpr T stateValueFromBits(uint32_t bits) {
    if constexpr (std::is_same_v<T, float>) {
        return floatFromBits(bits);
    } else if constexpr (std::is_same_v<T, bool>) {
        return bits != 0;
    } else {
        return static_cast<T>(bits);
    }
}

// Valid values per slot; floats accept any bits.
constexpr FieldSpec renderStateValueSpec(uint32_t slot) {
    switch (slot) {
        case kRsSrcColor:
        case kRsDstColor:
        case kRsSrcAlpha:
        case kRsDstAlpha:
            return belowField(kBlendFactorCount);
        case kRsColorOp:
        case kRsAlphaOp:
            return belowField(kBlendOpCount);
        case kRsZWrite:
            return boolField();
        case kRsZTest:
        case kRsFrontComp:
        case kRsBackComp:
            return belowField(kCompareFunctionCount);
        case kRsCull:
            return belowField(kCullModeCount);
        case kRsColorMask:
            return belowField(kColorWriteAll + 1);
        case kRsStencilRef:
        case kRsStencilReadMask:
        case kRsStencilWriteMask:
            return belowField(256);
        case kRsOffsetFactor:
        case kRsOffsetUnits:
            return valueField();
        default:
            return belowField(kStencilOpCount);
    }
}

constexpr std::array<FieldSpec, kRenderStateFieldCount> makeRenderStateSchema() {
    std::array<FieldSpec, kRenderStateFieldCount> schema{};
    schema[kRsBlendEnabled] = boolField();
    schema[kRsStencilEnabled] = boolField();
    for (uint32_t slot = 0; slot < kRsSlotCount; ++slot) {
        schema[renderStateValueField(slot)] = renderStateValueSpec(slot);
        schema[renderStatePropertyField(slot)] = stringField();
    }
    return schema;
}
inline constexpr std::array<FieldSpec, kRenderStateFieldCount> kRenderStateSchema =
    makeRenderStateSchema();

}  // namespace varc::pack
