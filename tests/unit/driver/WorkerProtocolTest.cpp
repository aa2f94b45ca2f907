// SPDX-License-Identifier: Apache-2.0
// The optimiser workers' framing and bodies: round trips, and damaged input as errors.
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstring>
#include <string>

#include "varc/driver/WorkerProtocol.h"

namespace varc::driver {
namespace {

// A connected socket pair, closed on destruction (either end may be closed early).
struct SocketPair {
    SocketPair() { EXPECT_EQ(::socketpair(AF_UNIX, SOCK_STREAM, 0, fds), 0); }
    ~SocketPair() {
        for (int& fd : fds) closeEnd(fd);
    }
    static void closeEnd(int& fd) {
        if (fd >= 0) ::close(fd);
        fd = -1;
    }
    int fds[2] = {-1, -1};
};

void writeRaw(int fd, const void* data, size_t size) {
    ASSERT_EQ(::write(fd, data, size), static_cast<ssize_t>(size));
}

TEST(WorkerProtocol, FramesRoundTripInOrder) {
    SocketPair pair;
    ASSERT_TRUE(writeFrame(pair.fds[0], "first"));
    ASSERT_TRUE(writeFrame(pair.fds[0], ""));
    Frame first = readFrame(pair.fds[1], 1000);
    Frame empty = readFrame(pair.fds[1], 1000);
    EXPECT_EQ(first.status, FrameStatus::Ok);
    EXPECT_EQ(first.bytes, "first");
    EXPECT_EQ(empty.status, FrameStatus::Ok);
    EXPECT_EQ(empty.bytes, "");
}

TEST(WorkerProtocol, EndBetweenFramesIsEndNotTruncation) {
    SocketPair pair;
    SocketPair::closeEnd(pair.fds[0]);
    EXPECT_EQ(readFrame(pair.fds[1], 1000).status, FrameStatus::End);
}

TEST(WorkerProtocol, EndInsideTheLengthOrTheBodyIsTruncation) {
    for (size_t cut : {2u, 4u + 3u}) {
        SocketPair pair;
        uint32_t length = 10;
        std::string bytes(reinterpret_cast<const char*>(&length), 4);
        bytes += "0123456789";
        writeRaw(pair.fds[0], bytes.data(), cut);
        SocketPair::closeEnd(pair.fds[0]);
        Frame frame = readFrame(pair.fds[1], 1000);
        EXPECT_EQ(frame.status, FrameStatus::Truncated) << cut;
        EXPECT_TRUE(frame.bytes.empty());
    }
}

TEST(WorkerProtocol, OversizedLengthIsRefusedBeforeReadingTheBody) {
    SocketPair pair;
    uint32_t length = kMaxFrameBytes + 1;
    writeRaw(pair.fds[0], &length, sizeof length);
    EXPECT_EQ(readFrame(pair.fds[1], 1000).status, FrameStatus::Oversized);
    EXPECT_FALSE(writeFrame(pair.fds[0], std::string(kMaxFrameBytes + 1, 'x')));
}

TEST(WorkerProtocol, SilenceTimesOut) {
    SocketPair pair;
    uint32_t length = 8;
    writeRaw(pair.fds[0], &length, sizeof length);  // a header, then nothing
    EXPECT_EQ(readFrame(pair.fds[1], 50).status, FrameStatus::TimedOut);
}

TEST(WorkerProtocol, WritingToADeadPeerFailsWithoutSigpipe) {
    SocketPair pair;
    SocketPair::closeEnd(pair.fds[1]);
    // Were SIGPIPE raised, the test process would end here.
    EXPECT_FALSE(writeFrame(pair.fds[0], std::string(1 << 20, 'x')));
}

TEST(WorkerProtocol, RequestsRoundTrip) {
    OptimizeRequest request{OptimizationLevel::Size, {0x07230203u, 1, 2, 3}};
    std::optional<OptimizeRequest> decoded = decodeRequest(encodeRequest(request));
    ASSERT_TRUE(decoded);
    EXPECT_EQ(decoded->level, OptimizationLevel::Size);
    EXPECT_EQ(decoded->spirv, request.spirv);
}

TEST(WorkerProtocol, DamagedRequestsAreRefused) {
    std::string bytes = encodeRequest({OptimizationLevel::None, {1, 2, 3}});
    for (size_t size = 0; size < bytes.size(); ++size)
        EXPECT_FALSE(decodeRequest(bytes.substr(0, size))) << size;
    EXPECT_FALSE(decodeRequest(bytes + "x"));  // trailing bytes
    std::string badLevel = bytes;
    badLevel[0] = 9;
    EXPECT_FALSE(decodeRequest(badLevel));
    std::string hugeCount = bytes;
    uint32_t count = 0xffffffffu;
    std::memcpy(hugeCount.data() + 4, &count, 4);  // more words than bytes follow
    EXPECT_FALSE(decodeRequest(hugeCount));
}

TEST(WorkerProtocol, OutcomesRoundTripAndDamagedOnesAreRefused) {
    OptimizeOutcome outcome;
    outcome.invalidInput = "word 5: bad";
    outcome.optimized.ok = true;
    outcome.optimized.message = "note";
    outcome.optimized.spirv = {4, 5};
    std::string bytes = encodeOutcome(outcome);
    std::optional<OptimizeOutcome> decoded = decodeOutcome(bytes);
    ASSERT_TRUE(decoded);
    EXPECT_EQ(decoded->invalidInput, outcome.invalidInput);
    EXPECT_TRUE(decoded->optimized.ok);
    EXPECT_EQ(decoded->optimized.message, "note");
    EXPECT_EQ(decoded->optimized.spirv, outcome.optimized.spirv);
    EXPECT_FALSE(decodeOutcome(encodeOutcome({})).value().invalidInput);
    for (size_t size = 0; size < bytes.size(); ++size)
        EXPECT_FALSE(decodeOutcome(bytes.substr(0, size))) << size;
}

}  // namespace
}  // namespace varc::driver
