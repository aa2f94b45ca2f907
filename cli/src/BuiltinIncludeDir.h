// SPDX-License-Identifier: Apache-2.0
// Where varc's built-in include files are when neither the command line nor the environment say.
#pragma once

#include <string>

namespace varc::cli {

// An installed varc (<prefix>/bin/varc, found through /proc/self/exe) uses
// <prefix>/share/varc/builtin when that folder exists; any other varc (the build tree's) uses
// the source tree's shaders/builtin it was configured from.
std::string defaultBuiltinIncludeDir();

}  // namespace varc::cli
