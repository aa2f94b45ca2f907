// SPDX-License-Identifier: Apache-2.0
// Converts a ShaderLab pass's render state (as written) to the pack's typed render state.
#include "varc/driver/RenderStateConversion.h"

#include <charconv>
#include <cstdint>
#include <string_view>

#include "varc/core/AsciiCase.h"

namespace varc::driver {

namespace {

using pack::StateField;
using shaderlab::StateValue;

template <typename T>
struct Named {
    std::string_view name;
    T value;
};

constexpr Named<pack::BlendFactor> kBlendFactors[] = {
    {"Zero", pack::BlendFactor::Zero},
    {"One", pack::BlendFactor::One},
    {"SrcColor", pack::BlendFactor::SrcColor},
    {"SrcAlpha", pack::BlendFactor::SrcAlpha},
    {"DstColor", pack::BlendFactor::DstColor},
    {"DstAlpha", pack::BlendFactor::DstAlpha},
    {"OneMinusSrcColor", pack::BlendFactor::OneMinusSrcColor},
    {"OneMinusSrcAlpha", pack::BlendFactor::OneMinusSrcAlpha},
    {"OneMinusDstColor", pack::BlendFactor::OneMinusDstColor},
    {"OneMinusDstAlpha", pack::BlendFactor::OneMinusDstAlpha},
    {"SrcAlphaSaturate", pack::BlendFactor::SrcAlphaSaturate},
};
constexpr Named<pack::BlendOp> kBlendOps[] = {
    {"Add", pack::BlendOp::Add},
    {"Sub", pack::BlendOp::Subtract},
    {"RevSub", pack::BlendOp::ReverseSubtract},
    {"Min", pack::BlendOp::Min},
    {"Max", pack::BlendOp::Max},
};
// `ZTest Off` and `Comp Disabled` turn the test off.
constexpr Named<pack::CompareFunction> kComparisons[] = {
    {"Less", pack::CompareFunction::Less},        {"Greater", pack::CompareFunction::Greater},
    {"LEqual", pack::CompareFunction::LessEqual}, {"GEqual", pack::CompareFunction::GreaterEqual},
    {"Equal", pack::CompareFunction::Equal},      {"NotEqual", pack::CompareFunction::NotEqual},
    {"Always", pack::CompareFunction::Always},    {"Never", pack::CompareFunction::Never},
    {"Off", pack::CompareFunction::Disabled},     {"Disabled", pack::CompareFunction::Disabled},
};
constexpr Named<pack::CullMode> kCullModes[] = {
    {"Back", pack::CullMode::Back}, {"Front", pack::CullMode::Front}, {"Off", pack::CullMode::Off}};
constexpr Named<pack::StencilOp> kStencilOps[] = {
    {"Keep", pack::StencilOp::Keep},
    {"Zero", pack::StencilOp::Zero},
    {"Replace", pack::StencilOp::Replace},
    {"IncrSat", pack::StencilOp::IncrementSaturate},
    {"DecrSat", pack::StencilOp::DecrementSaturate},
    {"Invert", pack::StencilOp::Invert},
    {"IncrWrap", pack::StencilOp::IncrementWrap},
    {"DecrWrap", pack::StencilOp::DecrementWrap},
};
constexpr Named<bool> kOnOff[] = {{"On", true}, {"Off", false}};

// Collects the errors of one conversion.
class Converter {
public:
    std::vector<std::string> errors;

    // Copies a property reference, or looks the literal up in |names|.
    template <typename T, size_t N>
    void named(const StateValue& in, StateField<T>& out, const Named<T> (&names)[N],
               std::string_view command, std::string_view what) {
        if (!in.isSet()) return;
        if (in.isProperty()) {
            out.property = in.property;
            return;
        }
        for (const Named<T>& entry : names) {
            if (equalsIgnoreAsciiCase(entry.name, in.literal)) {
                out = {entry.value, {}};  // a literal replaces a copied property reference
                return;
            }
        }
        std::string expected;
        for (const Named<T>& entry : names) {
            expected += (expected.empty() ? "" : ", ") + std::string(entry.name);
        }
        fail(command, std::string("unknown ") + std::string(what) + " '" + in.literal +
                          "' (expected " + expected + ")");
    }

    void byte(const StateValue& in, StateField<uint8_t>& out, std::string_view command) {
        if (!in.isSet()) return;
        if (in.isProperty()) {
            out.property = in.property;
            return;
        }
        unsigned value = 0;
        const char* end = in.literal.data() + in.literal.size();
        auto [ptr, ec] = std::from_chars(in.literal.data(), end, value);
        if (ec != std::errc() || ptr != end || value > 255) {
            fail(command, "expected an integer 0..255, got '" + in.literal + "'");
            return;
        }
        out.value = static_cast<uint8_t>(value);
    }

    void number(const StateValue& in, StateField<float>& out, std::string_view command) {
        if (!in.isSet()) return;
        if (in.isProperty()) {
            out.property = in.property;
            return;
        }
        float value = 0;
        const char* end = in.literal.data() + in.literal.size();
        auto [ptr, ec] = std::from_chars(in.literal.data(), end, value);
        if (ec != std::errc() || ptr != end) {
            fail(command, "expected a number, got '" + in.literal + "'");
            return;
        }
        out.value = value;
    }

    void colorMask(const StateValue& in, StateField<uint8_t>& out);

    void fail(std::string_view command, const std::string& message) {
        errors.push_back(std::string(command) + ": " + message);
    }
};

// `ColorMask 0`, `ColorMask RGB`, `ColorMask A`, any letters of RGBA in any case.
void Converter::colorMask(const StateValue& in, StateField<uint8_t>& out) {
    if (!in.isSet()) return;
    if (in.isProperty()) {
        out.property = in.property;
        return;
    }
    if (in.literal == "0") {
        out.value = 0;
        return;
    }
    uint8_t mask = 0;
    for (char c : in.literal) {
        switch (c) {
            case 'R':
            case 'r':
                mask |= pack::kColorWriteRed;
                break;
            case 'G':
            case 'g':
                mask |= pack::kColorWriteGreen;
                break;
            case 'B':
            case 'b':
                mask |= pack::kColorWriteBlue;
                break;
            case 'A':
            case 'a':
                mask |= pack::kColorWriteAlpha;
                break;
            default:
                fail("ColorMask", "expected 0 or letters of RGBA, got '" + in.literal + "'");
                return;
        }
    }
    out.value = in.literal.empty() ? pack::kColorWriteAll : mask;
}

void convertBlend(const shaderlab::BlendState& blend, pack::PackRenderState& out, Converter& c) {
    out.blendEnabled = !blend.off;
    if (blend.off) return;
    c.named(blend.src, out.srcColor, kBlendFactors, "Blend", "blend factor");
    c.named(blend.dst, out.dstColor, kBlendFactors, "Blend", "blend factor");
    out.srcAlpha = out.srcColor;
    out.dstAlpha = out.dstColor;
    c.named(blend.srcAlpha, out.srcAlpha, kBlendFactors, "Blend", "blend factor");
    c.named(blend.dstAlpha, out.dstAlpha, kBlendFactors, "Blend", "blend factor");
    c.named(blend.op, out.colorOp, kBlendOps, "BlendOp", "blend operation");
    out.alphaOp = out.colorOp;
    c.named(blend.opAlpha, out.alphaOp, kBlendOps, "BlendOp", "blend operation");
}

void convertFace(const shaderlab::StencilFace& face, pack::PackStencilFace& out, Converter& c) {
    c.named(face.comp, out.comp, kComparisons, "Stencil Comp", "comparison");
    c.named(face.pass, out.pass, kStencilOps, "Stencil Pass", "stencil operation");
    c.named(face.fail, out.fail, kStencilOps, "Stencil Fail", "stencil operation");
    c.named(face.zFail, out.zFail, kStencilOps, "Stencil ZFail", "stencil operation");
}

void convertStencil(const shaderlab::StencilState& stencil, pack::PackRenderState& out,
                    Converter& c) {
    out.stencilEnabled = true;
    c.byte(stencil.ref, out.stencilRef, "Stencil Ref");
    c.byte(stencil.readMask, out.stencilReadMask, "Stencil ReadMask");
    c.byte(stencil.writeMask, out.stencilWriteMask, "Stencil WriteMask");
    convertFace(stencil.front, out.front, c);
    convertFace(stencil.back, out.back, c);
}

}  // namespace

ConvertedRenderState fromShaderLab(const shaderlab::RenderState& state) {
    ConvertedRenderState result;
    pack::PackRenderState& out = result.state;
    Converter c;
    if (state.blend) convertBlend(*state.blend, out, c);
    c.named(state.zWrite, out.zWrite, kOnOff, "ZWrite", "value");
    c.named(state.zTest, out.zTest, kComparisons, "ZTest", "comparison");
    c.named(state.cull, out.cull, kCullModes, "Cull", "mode");
    c.colorMask(state.colorMask, out.colorMask);
    if (state.offset) {
        c.number(state.offset->first, out.offsetFactor, "Offset");
        c.number(state.offset->second, out.offsetUnits, "Offset");
    }
    if (state.stencil) convertStencil(*state.stencil, out, c);
    result.errors = std::move(c.errors);
    return result;
}

}  // namespace varc::driver
