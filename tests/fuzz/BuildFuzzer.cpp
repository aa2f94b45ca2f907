// SPDX-License-Identifier: Apache-2.0
// libFuzzer target for `varc build` itself: the input (a .shader file plus include files,
// FuzzInput.h) is written to a scratch folder and built by runCli, so ShaderLab, includes,
// keywords, glslang, the validator, the optimiser workers, pack assembly and the diagnostics
// printer all run as they do for a user.
//
// The optimiser runs where varc runs it, in worker processes: this binary is its own worker
// (LLVMFuzzerInitialize serves `__optimizer-worker` the way varc's main does). A crash inside a
// worker is therefore the isolation working (the build reports an error), not a finding; a crash
// in varc's own code or in glslang, which still runs in-process, ends the fuzzer and is one.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "FuzzInput.h"
#include "varc/cli/Cli.h"
#include "varc/cli/DriverOptions.h"
#include "varc/driver/OptimizerWorker.h"

namespace {

// Bounds that keep one input to seconds, so a 60 s run explores rather than times out: at most
// this many variants in a pass (a larger pass is refused before anything is compiled), and a
// worker that takes longer than this on one program is killed (varc's default is 300 s).
constexpr const char* kMaxVariants = "8";
constexpr const char* kWorkerTimeoutSeconds = "10";

std::filesystem::path gScratch;  // this process's folder: fuzz.shader, f1.h, ..., out.pack

void removeScratch() {
    std::error_code error;
    std::filesystem::remove_all(gScratch, error);
}

void writeFile(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int* argc, char*** argv) {
    // Spawned by the optimiser pool as `<this binary> __optimizer-worker`: serve, then leave
    // before libFuzzer parses anything.
    if (*argc == 2 && (*argv)[1] == varc::driver::kOptimizerWorkerCommand) {
        const char* workerArgv[] = {"varc", (*argv)[1]};
        std::exit(varc::cli::runCli(2, workerArgv, std::cout, std::cerr));
    }
    varc::cli::enableOptimizerWorkers();
    // No program cache (a hit would skip the compile being fuzzed); a shorter worker timeout.
    ::unsetenv("VARC_CACHE");
    ::unsetenv("VARC_CACHE_DIR");
    ::setenv("VARC_WORKER_TIMEOUT", kWorkerTimeoutSeconds, /*overwrite=*/0);
    std::string pattern =
        (std::filesystem::temp_directory_path() / "varc-build-fuzz-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) {
        std::perror("varc build fuzzer: mkdtemp");
        std::exit(1);
    }
    gScratch = pattern;
    std::atexit(removeScratch);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<std::string> files = varc::fuzz::splitFiles(varc::fuzz::asText(data, size));
    // A fresh folder each time, so no include file of an earlier input is found.
    removeScratch();
    std::filesystem::create_directory(gScratch);
    const std::string shader = (gScratch / "fuzz.shader").string();
    const std::string pack = (gScratch / "out.pack").string();
    writeFile(shader, files[0]);
    for (size_t i = 1; i < files.size(); ++i)
        writeFile(gScratch / varc::fuzz::includeName(i), files[i]);
    const char* argv[] = {"varc",
                          "build",
                          shader.c_str(),
                          "-o",
                          pack.c_str(),
                          "-j",
                          "1",
                          "--max-variants",
                          kMaxVariants,
                          "--builtin-include-dir",
                          VARC_BUILTIN_DIR};
    std::ostringstream out, err;  // printed, so the diagnostics printer is fuzzed too
    const int status = varc::cli::runCli(static_cast<int>(std::size(argv)), argv, out, err);
    // VARC_FUZZ_VERBOSE=1 (for triage, e.g. running one input): what varc printed, and its status.
    if (const char* verbose = std::getenv("VARC_FUZZ_VERBOSE"); verbose && *verbose == '1')
        std::cerr << err.str() << out.str() << "varc build: exit " << status << "\n";
    return 0;
}
