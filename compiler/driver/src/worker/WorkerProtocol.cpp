// SPDX-License-Identifier: Apache-2.0
// Frames (length + bytes, with a deadline and a size limit) and the optimiser's message bodies.
#include "varc/driver/WorkerProtocol.h"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>

namespace varc::driver {

namespace {

using Clock = std::chrono::steady_clock;

// Reads exactly |size| bytes into |out| by |deadline| (nullopt: none). |started| says whether
// part of the frame was read already, which turns an end of stream into Truncated.
FrameStatus readExactly(int fd, char* out, size_t size, std::optional<Clock::time_point> deadline,
                        bool started) {
    size_t done = 0;
    while (done < size) {
        int waitMs = -1;
        if (deadline) {
            auto left =
                std::chrono::duration_cast<std::chrono::milliseconds>(*deadline - Clock::now());
            if (left.count() <= 0) return FrameStatus::TimedOut;
            waitMs = static_cast<int>(left.count());
        }
        pollfd ready{fd, POLLIN, 0};
        int polled = ::poll(&ready, 1, waitMs);
        if (polled < 0 && errno == EINTR) continue;
        if (polled < 0) return FrameStatus::IoError;
        if (polled == 0) return FrameStatus::TimedOut;
        ssize_t got = ::read(fd, out + done, size - done);
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) return FrameStatus::IoError;
        if (got == 0) return started || done > 0 ? FrameStatus::Truncated : FrameStatus::End;
        done += static_cast<size_t>(got);
    }
    return FrameStatus::Ok;
}

// Appends |size| bytes of |data|; the reader below takes them back in order.
void put(std::string& out, const void* data, size_t size) {
    out.append(static_cast<const char*>(data), size);
}
void putU32(std::string& out, uint32_t value) { put(out, &value, sizeof value); }
void putText(std::string& out, std::string_view text) {
    putU32(out, static_cast<uint32_t>(text.size()));
    out.append(text);
}
void putWords(std::string& out, const std::vector<uint32_t>& words) {
    putU32(out, static_cast<uint32_t>(words.size()));
    put(out, words.data(), words.size() * sizeof(uint32_t));
}

// Bounds-checked reads of what put* wrote; any read past the end fails the whole decode.
class BodyReader {
public:
    explicit BodyReader(std::string_view bytes) : mBytes(bytes) {}
    bool u32(uint32_t& value) { return take(&value, sizeof value); }
    bool text(std::string& value) {
        uint32_t size = 0;
        if (!u32(size) || size > mBytes.size() - mAt) return false;
        value.assign(mBytes.substr(mAt, size));
        mAt += size;
        return true;
    }
    bool words(std::vector<uint32_t>& value) {
        uint32_t count = 0;
        if (!u32(count) || count > (mBytes.size() - mAt) / sizeof(uint32_t)) return false;
        value.resize(count);
        return take(value.data(), count * sizeof(uint32_t));
    }
    bool atEnd() const { return mAt == mBytes.size(); }

private:
    bool take(void* out, size_t size) {
        if (size > mBytes.size() - mAt) return false;
        if (size > 0) std::memcpy(out, mBytes.data() + mAt, size);
        mAt += size;
        return true;
    }
    std::string_view mBytes;
    size_t mAt = 0;
};

}  // namespace

Frame readFrame(int fd, int timeoutMs) {
    std::optional<Clock::time_point> deadline;
    if (timeoutMs >= 0) deadline = Clock::now() + std::chrono::milliseconds(timeoutMs);
    Frame frame;
    uint32_t size = 0;
    frame.status = readExactly(fd, reinterpret_cast<char*>(&size), sizeof size, deadline, false);
    if (frame.status != FrameStatus::Ok) return frame;
    if (size > kMaxFrameBytes) {
        frame.status = FrameStatus::Oversized;
        return frame;
    }
    frame.bytes.resize(size);
    frame.status = readExactly(fd, frame.bytes.data(), size, deadline, true);
    if (frame.status != FrameStatus::Ok) frame.bytes.clear();
    return frame;
}

bool writeFrame(int fd, std::string_view bytes) {
    if (bytes.size() > kMaxFrameBytes) return false;
    std::string out;
    putU32(out, static_cast<uint32_t>(bytes.size()));
    out.append(bytes);
    size_t done = 0;
    while (done < out.size()) {
        // send() with MSG_NOSIGNAL: a dead peer is an error to report, not a SIGPIPE.
        ssize_t sent = ::send(fd, out.data() + done, out.size() - done, MSG_NOSIGNAL);
        if (sent < 0 && errno == ENOTSOCK) sent = ::write(fd, out.data() + done, out.size() - done);
        if (sent < 0 && errno == EINTR) continue;
        if (sent <= 0) return false;
        done += static_cast<size_t>(sent);
    }
    return true;
}

std::string describeFrameStatus(FrameStatus status) {
    switch (status) {
        case FrameStatus::Ok:
            return "no error";
        case FrameStatus::End:
            return "the connection ended";
        case FrameStatus::Truncated:
            return "the connection ended inside a message";
        case FrameStatus::Oversized:
            return "a message exceeded the size limit";
        case FrameStatus::TimedOut:
            return "no answer before the deadline";
        case FrameStatus::IoError:
            return std::string("I/O error: ") + std::strerror(errno);
    }
    return "unknown";
}

std::string encodeRequest(const OptimizeRequest& request) {
    std::string out;
    putU32(out, static_cast<uint32_t>(request.level));
    putWords(out, request.spirv);
    return out;
}

std::optional<OptimizeRequest> decodeRequest(std::string_view bytes) {
    BodyReader reader(bytes);
    OptimizeRequest request;
    uint32_t level = 0;
    if (!reader.u32(level) || level > static_cast<uint32_t>(OptimizationLevel::Size))
        return std::nullopt;
    request.level = static_cast<OptimizationLevel>(level);
    if (!reader.words(request.spirv) || !reader.atEnd()) return std::nullopt;
    return request;
}

std::string encodeOutcome(const OptimizeOutcome& outcome) {
    std::string out;
    putU32(out, outcome.invalidInput ? 1 : 0);
    putText(out, outcome.invalidInput.value_or(""));
    putU32(out, outcome.optimized.ok ? 1 : 0);
    putText(out, outcome.optimized.message);
    putWords(out, outcome.optimized.spirv);
    return out;
}

std::optional<OptimizeOutcome> decodeOutcome(std::string_view bytes) {
    BodyReader reader(bytes);
    OptimizeOutcome outcome;
    uint32_t invalid = 0, ok = 0;
    std::string invalidMessage;
    if (!reader.u32(invalid) || invalid > 1 || !reader.text(invalidMessage) || !reader.u32(ok) ||
        ok > 1 || !reader.text(outcome.optimized.message) ||
        !reader.words(outcome.optimized.spirv) || !reader.atEnd())
        return std::nullopt;
    if (invalid) outcome.invalidInput = std::move(invalidMessage);
    outcome.optimized.ok = ok == 1;
    return outcome;
}

}  // namespace varc::driver
