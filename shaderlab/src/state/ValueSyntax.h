// SPDX-License-Identifier: Apache-2.0
// Shared value syntax: render-state values (`One`, `2`, `[_Prop]`), integers and numbers.
#pragma once

#include <optional>
#include <span>
#include <string_view>

#include "lex/Token.h"
#include "lex/TokenCursor.h"
#include "varc/shaderlab/RenderState.h"

namespace varc::shaderlab {

// Parses one value of render-state command |command| into |out|: a property reference
// `[_Name]`, a number when |allowNumber|, or an identifier from |names| (case-insensitive, kept
// as written). Errors: "invalid ZTest value 'Foo'; expected Less, ...", "expected a value for
// ZTest, found '}'". Example: `[_SrcBlend]` -> {property "_SrcBlend"}.
bool parseStateValue(TokenCursor& cursor, std::string_view command,
                     std::span<const std::string_view> names, bool allowNumber, StateValue& out);

// True when |names| holds |text| ignoring case.
bool containsName(std::span<const std::string_view> names, std::string_view text);

// The integer a Number token spells ("12", "-3"), or nullopt for "1.5", "1e3" or overflow.
std::optional<int> integerOf(const Token& token);
// The float a Number token spells ("-.5" -> -0.5), or nullopt when out of range.
std::optional<float> floatOf(const Token& token);

}  // namespace varc::shaderlab
