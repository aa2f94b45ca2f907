// SPDX-License-Identifier: Apache-2.0
// Length-prefixed frames over a socket between varc and its optimiser workers, and their bodies.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "varc/driver/SpirvOptimizer.h"

namespace varc::driver {

// A frame is a 32-bit length (host byte order: both ends are the same binary) and that many
// bytes. Larger frames are refused before anything is allocated.
constexpr uint32_t kMaxFrameBytes = 64u << 20;

enum class FrameStatus {
    Ok,
    End,        // the peer closed the connection between frames
    Truncated,  // the peer closed the connection inside a frame
    Oversized,  // the length exceeds kMaxFrameBytes
    TimedOut,   // the deadline passed first
    IoError,    // read/write failed (errno)
};

struct Frame {
    FrameStatus status = FrameStatus::Ok;
    std::string bytes;
};

// Reads one frame from |fd|; waits at most |timeoutMs| in all (-1: no limit).
Frame readFrame(int fd, int timeoutMs = -1);

// Writes one frame to |fd| (never raises SIGPIPE on a socket whose peer died). Returns false when
// it could not be written whole, or |bytes| is larger than kMaxFrameBytes.
bool writeFrame(int fd, std::string_view bytes);

// A short phrase for a failed status ("the connection ended inside a message").
std::string describeFrameStatus(FrameStatus status);

// One optimisation request: glslang's module and the recipe to run on it.
struct OptimizeRequest {
    OptimizationLevel level = OptimizationLevel::Performance;
    std::vector<uint32_t> spirv;
};

std::string encodeRequest(const OptimizeRequest& request);
std::optional<OptimizeRequest> decodeRequest(std::string_view bytes);  // nullopt: malformed
std::string encodeOutcome(const OptimizeOutcome& outcome);
std::optional<OptimizeOutcome> decodeOutcome(std::string_view bytes);  // nullopt: malformed

}  // namespace varc::driver
