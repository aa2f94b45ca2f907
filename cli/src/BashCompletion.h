// SPDX-License-Identifier: Apache-2.0
// The bash completion script for `varc`, generated from its CLI11 definition.
#pragma once

#include <string>

namespace CLI {
class App;
}

namespace varc::cli {

// A bash script defining `_varc` and `complete -F _varc varc`: the visible subcommands and the
// top-level options first; after a subcommand, its options (words starting with '-'), folders
// after options whose value is a DIR, files after the others and for positional arguments.
// Hidden subcommands (no group) are left out.
std::string bashCompletion(const CLI::App& app);

}  // namespace varc::cli
