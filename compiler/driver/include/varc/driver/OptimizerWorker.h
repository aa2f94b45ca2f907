// SPDX-License-Identifier: Apache-2.0
// The optimiser worker process: SPIRV-Tools run on requests read from a socket, out of varc.
#pragma once

#include <string_view>

namespace varc::driver {

// The hidden subcommand that makes `varc` a worker: `varc __optimizer-worker`, with the socket
// to its parent as standard input. Not an option users give; OptimizerPool spawns it.
constexpr std::string_view kOptimizerWorkerCommand = "__optimizer-worker";

// Serves OptimizeRequest frames from |fd| until the parent closes it; returns the exit status
// (0 after a clean end, 2 on a malformed or truncated request). Runs validateAndOptimize, so a
// crash in SPIRV-Tools ends this process, not the build.
//
// Fault injection for tests: VARC_TEST_WORKER_FAULT="ACTION:TEXT" makes the worker act on a
// request whose module contains TEXT (a name glslang kept, e.g. a function's): ACTION `segv`
// raises SIGSEGV, `segv-optimized` does so only for the -O/-Os recipes (not legalisation alone),
// `hang` sleeps forever.
int runOptimizerWorker(int fd);

}  // namespace varc::driver
