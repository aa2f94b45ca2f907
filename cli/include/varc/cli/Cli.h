// SPDX-License-Identifier: Apache-2.0
// The `varc` command-line tool as a library: main() only forwards to runCli().
#pragma once

#include <iosfwd>

namespace varc::cli {

// Runs one `varc` invocation. Output goes to |out|, diagnostics to |err|. Returns the process
// exit code (kExitOk, kExitFailure or kExitUsage from Options.h).
int runCli(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace varc::cli
