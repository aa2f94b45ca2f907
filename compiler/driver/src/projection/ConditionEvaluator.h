// SPDX-License-Identifier: Apache-2.0
// Evaluates a `#if` / `#elif` expression as a C preprocessor does, looking every macro up through
// the walk's scope (which records the keywords it is asked about).
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "ConditionalText.h"

namespace varc::driver::projection {

// The macros in force at a point of the walk.
class MacroScope {
public:
    virtual ~MacroScope() = default;
    // The #define in force for |name|, or nullptr when |name| is not defined.
    virtual const PpLine* macro(std::string_view name) = 0;
};

// The value of |tokens| (`defined`, macro expansion, integer arithmetic), or nullopt when the
// expression holds what this evaluator does not model (token pasting or stringizing, floating
// literals, `true`, division by zero, values beyond 32 bits): the caller then gives up on the
// text. Every name expansion reaches is looked up (both sides of `&&`, `||` and `?:`), so the
// scope sees a superset of the lookups of a short-circuiting preprocessor.
std::optional<long long> evaluateCondition(const std::vector<std::string_view>& tokens,
                                           MacroScope& scope);

}  // namespace varc::driver::projection
