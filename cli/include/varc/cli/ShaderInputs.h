// SPDX-License-Identifier: Apache-2.0
// Turns the PATH arguments of varc commands into a sorted list of .shader files.
#pragma once

#include <string>
#include <vector>

#include "varc/core/Diagnostic.h"

namespace varc::cli {

// Files are taken as given; directories are searched recursively for `*.shader` files, sorted
// by path so output is stable. A missing path is an error, and so is a pack given as a file
// (one sentence naming it, not its bytes quoted as source). Duplicates are dropped.
std::vector<std::string> findShaderFiles(const std::vector<std::string>& paths,
                                         DiagnosticSink& sink);

}  // namespace varc::cli
