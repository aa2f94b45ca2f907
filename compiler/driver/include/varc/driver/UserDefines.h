// SPDX-License-Identifier: Apache-2.0
// Object-like macros a program text defines itself, so the predefined macros varc puts before
// the text can match them: Unity's HLSL compilers warn about a redefined macro and go on,
// glslang stops with "Macro redefined; different substitutions".
#pragma once

#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "varc/driver/PredefinedMacro.h"

namespace varc::driver {

class UserDefines {
public:
    // Collects each `#define UNITY_PASS_<NAME>` line of |text| whose replacement is empty or 1
    // (the first definition of a name wins; `//` comments and trailing blanks are not part of
    // the replacement). Only those: other predefined macros (SHADER_TARGET, keywords) keep
    // varc's value, since a text's `#ifndef X` / `#define X default` must not override it.
    // Example: "#define UNITY_PASS_FORWARDBASE\n" defines UNITY_PASS_FORWARDBASE as "".
    explicit UserDefines(std::string_view text);

    // Gives every definition in |macros| whose name the text defines itself the text's own
    // replacement, so glslang sees the same definition twice (no error) and the text's
    // `#ifdef NAME` tests behave as they would have. Other macros are left as they are.
    // Example: text "#define UNITY_PASS_FORWARDBASE", macro UNITY_PASS_FORWARDBASE = "1"
    // -> UNITY_PASS_FORWARDBASE = "" (written "#define UNITY_PASS_FORWARDBASE \n").
    void adopt(std::vector<PredefinedMacro>& macros) const;

    bool empty() const { return mReplacements.empty(); }

private:
    std::unordered_map<std::string, std::string> mReplacements;
};

}  // namespace varc::driver
