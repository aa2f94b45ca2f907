// SPDX-License-Identifier: Apache-2.0
// The worker's request loop, with the fault-injection hook the isolation tests use.
#include "varc/driver/OptimizerWorker.h"

#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <string>

#include "varc/driver/WorkerProtocol.h"

namespace varc::driver {

namespace {

// Whether the bytes of |spirv| contain |text| (SPIR-V packs names as nul-terminated bytes).
bool moduleContains(const std::vector<uint32_t>& spirv, std::string_view text) {
    std::string_view bytes(reinterpret_cast<const char*>(spirv.data()),
                           spirv.size() * sizeof(uint32_t));
    return !text.empty() && bytes.find(text) != std::string_view::npos;
}

// Acts on VARC_TEST_WORKER_FAULT (see the header) before |request| is served.
void injectFault(const OptimizeRequest& request) {
    const char* fault = std::getenv("VARC_TEST_WORKER_FAULT");
    if (!fault) return;
    std::string_view spec(fault);
    size_t colon = spec.find(':');
    if (colon == std::string_view::npos) return;
    std::string_view action = spec.substr(0, colon);
    if (!moduleContains(request.spirv, spec.substr(colon + 1))) return;
    const bool optimizing = request.level != OptimizationLevel::None;
    if (action == "segv" || (action == "segv-optimized" && optimizing)) {
        // The default action, as a real crash in SPIRV-Tools would have it (a sanitizer's
        // handler would otherwise turn the signal into an exit status).
        std::signal(SIGSEGV, SIG_DFL);
        std::raise(SIGSEGV);
    }
    if (action == "hang") {
        for (;;) ::pause();
    }
}

}  // namespace

int runOptimizerWorker(int fd) {
    for (;;) {
        Frame frame = readFrame(fd);
        if (frame.status == FrameStatus::End) return 0;
        if (frame.status != FrameStatus::Ok) return 2;
        std::optional<OptimizeRequest> request = decodeRequest(frame.bytes);
        if (!request) return 2;
        injectFault(*request);
        if (!writeFrame(fd, encodeOutcome(validateAndOptimize(request->spirv, request->level))))
            return 2;
    }
}

}  // namespace varc::driver
