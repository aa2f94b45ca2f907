// SPDX-License-Identifier: Apache-2.0
// How a text's braces can change from one variant to another: which macros expand to braces
// that do not balance, and which conditional groups leave the block structure around them alone.
#pragma once

#include <string_view>
#include <unordered_set>
#include <vector>

#include "ConditionalText.h"

namespace varc::driver::projection {

// The macros some #define of which expands, directly or through other macros, to braces that
// do not balance or that close before they open (`CBUFFER_END`'s `}`, `} else {`). Macros whose
// braces balance (`{ a; }`) change no block structure wherever they expand.
std::unordered_set<std::string_view> unbalancedBraceMacros(const std::vector<PpLine>& lines);

// Sets PpLine::clean on each #if/#ifdef/#ifndef of |lines| (linked by ConditionalText) whose
// every branch, nested groups included, holds only text and clean groups, names no macro of
// |braceMacros|, and has braces that balance without closing one opened before the group. Such a
// group inside a function body changes that body's text and nothing else, whichever branch a
// variant takes.
void markCleanGroups(std::vector<PpLine>& lines,
                     const std::unordered_set<std::string_view>& braceMacros);

}  // namespace varc::driver::projection
