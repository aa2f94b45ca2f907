// SPDX-License-Identifier: Apache-2.0
// Typed fixed-function render state of a pass, as stored in a pack (values may name properties).
#pragma once

#include <cstdint>
#include <string>

namespace varc::pack {

// Enumerators carry Unity's numeric values (UnityEngine.Rendering.*), so a material property
// referenced by a state field (`Blend [_SrcBlend] [_DstBlend]`) converts with a plain cast.
enum class BlendFactor : uint8_t {
    Zero = 0,
    One = 1,
    DstColor = 2,
    SrcColor = 3,
    OneMinusDstColor = 4,
    SrcAlpha = 5,
    OneMinusSrcColor = 6,
    DstAlpha = 7,
    OneMinusDstAlpha = 8,
    SrcAlphaSaturate = 9,
    OneMinusSrcAlpha = 10,
};
inline constexpr uint32_t kBlendFactorCount = 11;

enum class BlendOp : uint8_t { Add = 0, Subtract = 1, ReverseSubtract = 2, Min = 3, Max = 4 };
inline constexpr uint32_t kBlendOpCount = 5;

// Disabled turns the test off (`ZTest Off`): the runtime treats it as "always pass".
enum class CompareFunction : uint8_t {
    Disabled = 0,
    Never = 1,
    Less = 2,
    Equal = 3,
    LessEqual = 4,
    Greater = 5,
    NotEqual = 6,
    GreaterEqual = 7,
    Always = 8,
};
inline constexpr uint32_t kCompareFunctionCount = 9;

enum class CullMode : uint8_t { Off = 0, Front = 1, Back = 2 };
inline constexpr uint32_t kCullModeCount = 3;

enum class StencilOp : uint8_t {
    Keep = 0,
    Zero = 1,
    Replace = 2,
    IncrementSaturate = 3,
    DecrementSaturate = 4,
    Invert = 5,
    IncrementWrap = 6,
    DecrementWrap = 7,
};
inline constexpr uint32_t kStencilOpCount = 8;

// Unity's ColorWriteMask bits (note: not Vulkan's order, which is R=1, G=2, B=4, A=8).
inline constexpr uint8_t kColorWriteAlpha = 1;
inline constexpr uint8_t kColorWriteBlue = 2;
inline constexpr uint8_t kColorWriteGreen = 4;
inline constexpr uint8_t kColorWriteRed = 8;
inline constexpr uint8_t kColorWriteAll = 15;

// One state value: a literal, or a material property that overrides it at runtime. When
// |property| is set, |value| is Unity's default for the field, used if the material lacks it.
template <typename T>
struct StateField {
    T value{};
    std::string property;  // "_SrcBlend" for `[_SrcBlend]`; "" for a literal

    bool isProperty() const { return !property.empty(); }
    friend bool operator==(const StateField&, const StateField&) = default;
};

struct PackStencilFace {
    StateField<CompareFunction> comp{CompareFunction::Always, {}};
    StateField<StencilOp> pass{StencilOp::Keep, {}};
    StateField<StencilOp> fail{StencilOp::Keep, {}};
    StateField<StencilOp> zFail{StencilOp::Keep, {}};
    friend bool operator==(const PackStencilFace&, const PackStencilFace&) = default;
};

// Defaults are Unity's: Blend Off, ZWrite On, ZTest LEqual, Cull Back, ColorMask RGBA,
// Offset 0 0, no stencil (Ref 0, ReadMask 255, WriteMask 255, Comp Always, ops Keep).
struct PackRenderState {
    bool blendEnabled = false;
    StateField<BlendFactor> srcColor{BlendFactor::One, {}};
    StateField<BlendFactor> dstColor{BlendFactor::Zero, {}};
    StateField<BlendFactor> srcAlpha{BlendFactor::One, {}};
    StateField<BlendFactor> dstAlpha{BlendFactor::Zero, {}};
    StateField<BlendOp> colorOp{BlendOp::Add, {}};
    StateField<BlendOp> alphaOp{BlendOp::Add, {}};

    StateField<bool> zWrite{true, {}};
    StateField<CompareFunction> zTest{CompareFunction::LessEqual, {}};
    StateField<CullMode> cull{CullMode::Back, {}};
    StateField<uint8_t> colorMask{kColorWriteAll, {}};
    StateField<float> offsetFactor{0.0f, {}};
    StateField<float> offsetUnits{0.0f, {}};

    bool stencilEnabled = false;
    StateField<uint8_t> stencilRef{0, {}};
    StateField<uint8_t> stencilReadMask{255, {}};
    StateField<uint8_t> stencilWriteMask{255, {}};
    PackStencilFace front, back;

    friend bool operator==(const PackRenderState&, const PackRenderState&) = default;
};

}  // namespace varc::pack
