// SPDX-License-Identifier: Apache-2.0
// From the parsed command line to the compile driver: the one place `build` and `explain` get
// their driver::BuildOptions.
#pragma once

#include <string>

#include "varc/cli/Options.h"
#include "varc/driver/CompileDriver.h"

namespace varc::cli {

// The driver's options for |compile| read with |input|: every flag copied, the cache levels
// opened (nullptr without any), source paths recorded relative to --project-root (default: the
// current folder) with the --file-prefix-map rules. Left to the caller: progress and
// keepPrunedSources. CompileOptions{} gives the driver's defaults.
driver::BuildOptions toBuildOptions(const CompileOptions& compile, const ShaderInputOptions& input);

// Lets toBuildOptions give the driver an optimiser pool that re-executes this program as its
// workers (`__optimizer-worker`, which runCli serves). Only the `varc` executable calls it: a test
// binary linking the CLI library would otherwise spawn copies of itself. Without it SPIRV-Tools
// runs in-process.
void enableOptimizerWorkers();

// "-O0", "-O" or "-Os": how the flag, and the pack's build fingerprint, name |level|.
std::string optimizationFlag(driver::OptimizationLevel level);

}  // namespace varc::cli
