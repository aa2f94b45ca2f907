// SPDX-License-Identifier: Apache-2.0
// Reading a CLI11 definition back: visible subcommands and option spellings, for the generated
// man page and bash completion.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace varc::cli {

// The subcommands --help lists (hidden ones have an empty group), in definition order.
std::vector<const CLI::App*> visibleSubcommands(const CLI::App& app);

// Every spelling of a named option: "-o", "--output"; empty for positional arguments.
std::vector<std::string> optionSpellings(const CLI::Option& option);

// Whether the option is a flag (takes no value).
bool isFlag(const CLI::Option& option);

// What the option's value is called in help: its type name without the validators CLI11
// appends ("N:POSITIVE" -> "N"), "VALUE" when it has none.
std::string valueName(const CLI::Option& option);

}  // namespace varc::cli
