// SPDX-License-Identifier: Apache-2.0
// Accepts and discards legacy fixed-function commands (Lighting, Material, SetTexture, Fog, ...).
#include "state/LegacyCommandSkipper.h"

#include <string>
#include <string_view>

#include "state/ValueSyntax.h"
#include "varc/core/Check.h"

namespace varc::shaderlab {
namespace {

constexpr std::string_view kWordArguments[] = {
    "On", "Off", "True", "False", "AmbientAndDiffuse", "Emission"};
constexpr std::string_view kAlphaTestComparisons[] = {
    "Off", "Less", "Greater", "LEqual", "GEqual", "Equal", "NotEqual", "Always", "Never"};

// Commands taking one word argument, and commands taking a `{ ... }` block.
constexpr std::string_view kWordCommands[] = {"Lighting", "SeparateSpecular", "ColorMaterial"};
constexpr std::string_view kBlockCommands[] = {"Material", "Fog", "BindChannels"};

}  // namespace

bool LegacyCommandSkipper::isLegacyCommand(const Token& token) {
    if (!token.is(TokenKind::Identifier)) return false;
    return containsName(kWordCommands, token.text) || containsName(kBlockCommands, token.text) ||
           token.isKeyword("SetTexture") || token.isKeyword("AlphaTest");
}

bool LegacyCommandSkipper::skip() {
    Token keyword = mCursor.next();
    VARC_CHECK(isLegacyCommand(keyword)) << "not a legacy command: " << keyword.text;
    if (keyword.isKeyword("SetTexture")) return skipSetTexture(keyword);
    if (keyword.isKeyword("AlphaTest")) return skipAlphaTest();
    if (containsName(kBlockCommands, keyword.text)) return skipBlock(keyword);
    return skipWord(keyword, !keyword.isKeyword("SeparateSpecular"));
}

// `Lighting Off`, `ColorMaterial Emission`; `SeparateSpecular` may stand alone.
bool LegacyCommandSkipper::skipWord(const Token& keyword, bool required) {
    const Token& token = mCursor.peek();
    if (token.is(TokenKind::Identifier) && containsName(kWordArguments, token.text)) {
        mCursor.next();
        return true;
    }
    if (!required) return true;
    return mCursor.unexpected("a value for " + std::string(keyword.text));
}

bool LegacyCommandSkipper::skipBlock(const Token& keyword) {
    Token open;
    if (!mCursor.expectSymbol('{', "after " + std::string(keyword.text), &open)) return false;
    return mCursor.skipBlock(open);
}

// `SetTexture [_MainTex] { combine texture * primary }`.
bool LegacyCommandSkipper::skipSetTexture(const Token& keyword) {
    StateValue texture;
    if (!parseStateValue(mCursor, "SetTexture", {}, false, texture)) return false;
    return skipBlock(keyword);
}

// `AlphaTest Off`, `AlphaTest Greater 0.5`, `AlphaTest GEqual [_Cutoff]`.
bool LegacyCommandSkipper::skipAlphaTest() {
    StateValue comparison;
    if (!parseStateValue(mCursor, "AlphaTest", kAlphaTestComparisons, false, comparison)) {
        return false;
    }
    const Token& token = mCursor.peek();
    if (equalsIgnoreAsciiCase(comparison.literal, "Off")) return true;
    if (!token.is(TokenKind::Number) && !token.isSymbol('[')) return true;
    StateValue reference;
    return parseStateValue(mCursor, "AlphaTest", {}, true, reference);
}

}  // namespace varc::shaderlab
