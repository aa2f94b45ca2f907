// SPDX-License-Identifier: Apache-2.0
// A `#pragma` directive's text with its location, handed from the includes to the variants module.
#pragma once

#include <string>

#include "varc/core/SourceLocation.h"

namespace varc {

struct PragmaLine {
    std::string text;          // everything after "#pragma", trimmed: "multi_compile _ A"
    SourceLocation location;   // location of the '#'
};

}  // namespace varc
