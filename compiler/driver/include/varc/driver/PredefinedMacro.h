// SPDX-License-Identifier: Apache-2.0
// The macros varc puts before a program, as a list: filtered and adjusted as data, written once.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace varc::driver {

// One line of a program's preamble: `#define name value` or `#undef name`. |name| may carry a
// parameter list (`GetRenderTargetSampleCount()`); identifier() is the macro's name alone.
struct PredefinedMacro {
    enum class Kind { Define, Undef };
    Kind kind = Kind::Define;
    std::string name;
    std::string value;

    // "GetRenderTargetSampleCount()" -> "GetRenderTargetSampleCount"; "POINT" -> "POINT".
    std::string_view identifier() const;
};

// The text glslang sees before the program: one line per macro, in order.
// Example: {Define POINT 1, Undef GL_core_profile} -> "#define POINT 1\n#undef GL_core_profile\n".
std::string writePreamble(const std::vector<PredefinedMacro>& macros);

}  // namespace varc::driver
