// SPDX-License-Identifier: Apache-2.0
// The one place that decides how `#line` directives are written into expanded source.
#include "LineDirective.h"

namespace varc::includes {

void writeLineDirective(std::string& out, uint32_t line, FileId file) {
    out += "#line ";
    out += std::to_string(line);
    out += ' ';
    out += std::to_string(file);
    out += '\n';
}

}  // namespace varc::includes
