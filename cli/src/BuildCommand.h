// SPDX-License-Identifier: Apache-2.0
// `varc build`, run by the command dispatcher (Cli.cpp).
#pragma once

#include <ostream>

#include "Session.h"
#include "varc/cli/Options.h"

namespace varc::cli {

// Builds the pack `options` describe; the exit status (kExitOk, kExitFailure).
int runBuild(const BuildCommandOptions& options, Session& session, std::ostream& out,
             std::ostream& err);

}  // namespace varc::cli
