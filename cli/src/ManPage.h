// SPDX-License-Identifier: Apache-2.0
// The varc(1) man page, generated from the CLI11 definition.
#pragma once

#include <string>

namespace CLI {
class App;
}

namespace varc::cli {

// roff (man macros) for section 1: NAME, SYNOPSIS, DESCRIPTION, OPTIONS (top level), one
// COMMANDS subsection per visible subcommand with its arguments and options, ENVIRONMENT and
// FILES. |version| goes in the title line.
std::string manPage(const CLI::App& app, const std::string& version);

}  // namespace varc::cli
