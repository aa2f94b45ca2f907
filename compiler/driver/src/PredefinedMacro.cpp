// SPDX-License-Identifier: Apache-2.0
// The macros varc puts before a program, as a list: filtered and adjusted as data, written once.
#include "varc/driver/PredefinedMacro.h"

namespace varc::driver {

std::string_view PredefinedMacro::identifier() const {
    std::string_view text = name;
    return text.substr(0, text.find('('));
}

std::string writePreamble(const std::vector<PredefinedMacro>& macros) {
    std::string text;
    for (const PredefinedMacro& macro : macros) {
        if (macro.kind == PredefinedMacro::Kind::Undef) {
            text += "#undef " + macro.name + "\n";
        } else {
            text += "#define " + macro.name + " " + macro.value + "\n";
        }
    }
    return text;
}

}  // namespace varc::driver
