// SPDX-License-Identifier: Apache-2.0
// Parses render-state commands (Blend, ZWrite, Stencil, ...) and skips legacy fixed-function ones.
#include "state/RenderStateParser.h"

#include <string_view>

#include "state/LegacyCommandSkipper.h"
#include "state/StencilParser.h"
#include "state/ValueSyntax.h"
#include "varc/core/AsciiCase.h"

namespace varc::shaderlab {
namespace {

// clang-format off
constexpr std::string_view kBlendFactors[] = {
    "One", "Zero", "SrcColor", "SrcAlpha", "SrcAlphaSaturate", "DstColor", "DstAlpha",
    "OneMinusSrcColor", "OneMinusSrcAlpha", "OneMinusDstColor", "OneMinusDstAlpha"};
constexpr std::string_view kBlendOps[] = {
    "Add", "Sub", "RevSub", "Min", "Max",
    "LogicalClear", "LogicalSet", "LogicalCopy", "LogicalCopyInverted", "LogicalNoop",
    "LogicalInvert", "LogicalAnd", "LogicalNand", "LogicalOr", "LogicalNor", "LogicalXor",
    "LogicalEquiv", "LogicalAndReverse", "LogicalAndInverted", "LogicalOrReverse",
    "LogicalOrInverted", "Multiply", "Screen", "Overlay", "Darken", "Lighten", "ColorDodge",
    "ColorBurn", "HardLight", "SoftLight", "Difference", "Exclusion", "HSLHue", "HSLSaturation",
    "HSLColor", "HSLLuminosity"};
// clang-format on
constexpr std::string_view kCompareFunctions[] = {
    "Less", "Greater", "LEqual", "GEqual", "Equal", "NotEqual", "Always", "Never", "Disabled"};
// ZTest also takes Off and On, as Unity accepts them (image effects write `ZTest Off`).
constexpr std::string_view kDepthCompareFunctions[] = {
    "Less",  "Greater", "LEqual",   "GEqual", "Equal", "NotEqual",
    "Always", "Never",  "Disabled", "Off",    "On"};
constexpr std::string_view kCullModes[] = {"Back", "Front", "Off"};
constexpr std::string_view kOnOff[] = {"On", "Off"};
constexpr std::string_view kTrueFalse[] = {"True", "False", "On", "Off"};
// The render target index of `Blend 1 One One` / `ColorMask RGB 1`: 0..7.
constexpr int kMaxRenderTarget = 7;

// `ColorMask` takes 0 or a combination of the channel letters R, G, B, A.
bool isColorMaskName(std::string_view text) {
    if (text.empty()) return false;
    for (char c : text) {
        if (std::string_view("RGBArgba").find(c) == std::string_view::npos) return false;
    }
    return true;
}

}  // namespace

std::span<const RenderStateParser::Command> RenderStateParser::commands() {
    static constexpr Command kCommands[] = {
        {"Blend", &RenderStateParser::parseBlend},
        {"BlendOp", &RenderStateParser::parseBlendOp},
        {"ColorMask", &RenderStateParser::parseColorMask},
        {"Offset", &RenderStateParser::parseOffset},
        {"Stencil", &RenderStateParser::parseStencil},
        {"ZWrite", &RenderStateParser::parseZWrite},
        {"ZTest", &RenderStateParser::parseZTest},
        {"Cull", &RenderStateParser::parseCull},
        {"AlphaToMask", &RenderStateParser::parseAlphaToMask},
        {"Conservative", &RenderStateParser::parseConservative},
        {"ZClip", &RenderStateParser::parseZClip},
    };
    return kCommands;
}

CommandResult RenderStateParser::tryParse(RenderState& state) {
    const Token& token = mCursor.peek();
    if (LegacyCommandSkipper::isLegacyCommand(token)) {
        bool ok = LegacyCommandSkipper(mCursor).skip();
        return ok ? CommandResult::Parsed : CommandResult::Failed;
    }
    for (const Command& command : commands()) {
        if (token.isKeyword(command.name)) {
            mCursor.next();
            bool ok = (this->*command.handler)(state);
            return ok ? CommandResult::Parsed : CommandResult::Failed;
        }
    }
    return CommandResult::NotACommand;
}

bool RenderStateParser::isCommand(const Token& token) {
    for (const Command& command : commands()) {
        if (token.isKeyword(command.name)) return true;
    }
    return LegacyCommandSkipper::isLegacyCommand(token);
}

// `Blend [target] Off` or `Blend [target] Src Dst [, SrcA DstA]`.
bool RenderStateParser::parseBlend(RenderState& state) {
    int target = 0;
    if (!parseRenderTarget(target)) return false;
    BlendState written;
    if (mCursor.peek().isKeyword("Off")) {
        mCursor.next();
        written.off = true;
    } else if (!parseBlendFactors(written)) {
        return false;
    }
    if (target != 0) return true;
    BlendState& blend = state.blend ? *state.blend : state.blend.emplace();
    written.op = blend.op;  // an earlier BlendOp in this scope stays
    written.opAlpha = blend.opAlpha;
    blend = written;
    return true;
}

bool RenderStateParser::parseBlendFactors(BlendState& blend) {
    if (!parseStateValue(mCursor, "Blend", kBlendFactors, false, blend.src) ||
        !parseStateValue(mCursor, "Blend", kBlendFactors, false, blend.dst)) {
        return false;
    }
    if (!mCursor.peek().isSymbol(',')) return true;
    mCursor.next();
    return parseStateValue(mCursor, "Blend", kBlendFactors, false, blend.srcAlpha) &&
           parseStateValue(mCursor, "Blend", kBlendFactors, false, blend.dstAlpha);
}

// `BlendOp [target] Op [, OpAlpha]`.
bool RenderStateParser::parseBlendOp(RenderState& state) {
    int target = 0;
    StateValue op, opAlpha;
    if (!parseRenderTarget(target) || !parseStateValue(mCursor, "BlendOp", kBlendOps, false, op)) {
        return false;
    }
    if (mCursor.peek().isSymbol(',')) {
        mCursor.next();
        if (!parseStateValue(mCursor, "BlendOp", kBlendOps, false, opAlpha)) return false;
    }
    if (target != 0) return true;
    BlendState& blend = state.blend ? *state.blend : state.blend.emplace();
    blend.op = op;
    blend.opAlpha = opAlpha;
    return true;
}

// An optional render target index before Blend/BlendOp factors or after a ColorMask value.
bool RenderStateParser::parseRenderTarget(int& target) {
    const Token& token = mCursor.peek();
    if (!token.is(TokenKind::Number)) return true;
    std::optional<int> value = integerOf(token);
    if (!value || *value < 0 || *value > kMaxRenderTarget) {
        return mCursor.fail(token.location, "invalid render target index " + token.describe() +
                                                "; expected 0 to 7");
    }
    target = *value;
    mCursor.next();
    return true;
}

// `ColorMask RGB|A|0|[_Prop] [target]`.
bool RenderStateParser::parseColorMask(RenderState& state) {
    const Token& token = mCursor.peek();
    StateValue mask;
    if (token.is(TokenKind::Identifier) && isColorMaskName(token.text)) {
        mask.literal = std::string(mCursor.next().text);
    } else if (token.is(TokenKind::Number) && integerOf(token) == 0) {
        mask.literal = std::string(mCursor.next().text);
    } else if (token.isSymbol('[')) {
        if (!parseStateValue(mCursor, "ColorMask", {}, false, mask)) return false;
    } else if (token.is(TokenKind::Identifier) || token.is(TokenKind::Number)) {
        return mCursor.fail(token.location, "invalid ColorMask value " + token.describe() +
                                                "; expected 0 or channels such as RGB, RGBA, A");
    } else {
        return mCursor.unexpected("a value for ColorMask");
    }
    int target = 0;
    if (!parseRenderTarget(target)) return false;
    if (target == 0) state.colorMask = mask;
    return true;
}

// `Offset factor, units`, each a number or a property reference.
bool RenderStateParser::parseOffset(RenderState& state) {
    StateValue factor, units;
    if (!parseStateValue(mCursor, "Offset", {}, true, factor) ||
        !mCursor.expectSymbol(',', "between Offset factor and units") ||
        !parseStateValue(mCursor, "Offset", {}, true, units)) {
        return false;
    }
    state.offset = std::make_pair(factor, units);
    return true;
}

bool RenderStateParser::parseStencil(RenderState& state) {
    StencilState& stencil = state.stencil ? *state.stencil : state.stencil.emplace();
    return StencilParser(mCursor).parse(stencil);
}

bool RenderStateParser::parseZWrite(RenderState& state) {
    return parseStateValue(mCursor, "ZWrite", kOnOff, false, state.zWrite);
}

// `ZTest Off` turns the depth test off (Disabled); `ZTest On` is the default test, LEqual.
bool RenderStateParser::parseZTest(RenderState& state) {
    if (!parseStateValue(mCursor, "ZTest", kDepthCompareFunctions, false, state.zTest)) {
        return false;
    }
    if (equalsIgnoreAsciiCase(state.zTest.literal, "Off")) state.zTest.literal = "Disabled";
    if (equalsIgnoreAsciiCase(state.zTest.literal, "On")) state.zTest.literal = "LEqual";
    return true;
}

bool RenderStateParser::parseCull(RenderState& state) {
    return parseStateValue(mCursor, "Cull", kCullModes, false, state.cull);
}

bool RenderStateParser::parseAlphaToMask(RenderState& state) {
    // Unity's ShaderLab reads AlphaToMask as a boolean: True and False mean On and Off.
    return parseStateValue(mCursor, "AlphaToMask", kTrueFalse, false, state.alphaToMask);
}

bool RenderStateParser::parseConservative(RenderState& state) {
    return parseStateValue(mCursor, "Conservative", kTrueFalse, false, state.conservative);
}

bool RenderStateParser::parseZClip(RenderState& state) {
    return parseStateValue(mCursor, "ZClip", kTrueFalse, false, state.zClip);
}

}  // namespace varc::shaderlab
