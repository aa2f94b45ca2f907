// SPDX-License-Identifier: Apache-2.0
// The `varc` executable: a thin wrapper around varc::cli::runCli.
#include <iostream>
#include <new>

#include "varc/cli/Cli.h"
#include "varc/cli/DriverOptions.h"
#include "varc/core/AtomicFile.h"

int main(int argc, char** argv) {
    varc::removeTemporariesOnTerminationSignals();
    varc::cli::enableOptimizerWorkers();
    try {
        return varc::cli::runCli(argc, argv, std::cout, std::cerr);
    } catch (const std::bad_alloc&) {
        std::cerr << "varc: error: out of memory\n";
    } catch (const std::exception& e) {
        std::cerr << "varc: internal error: " << e.what() << "\n";
    }
    return 3;
}
