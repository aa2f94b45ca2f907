// SPDX-License-Identifier: Apache-2.0
// RedisStorage without a server: an unreachable or silent remote fails fast, once, and never
// throws or stalls; SIGPIPE never ends the process. (Against a real redis-server: tests/cache.)
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>

#include "varc/cache/RedisStorage.h"

namespace varc::cache {
namespace {

// A loopback port nobody listens on: bound, then closed.
uint16_t closedPort() {
    int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address));
    socklen_t length = sizeof(address);
    ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length);
    ::close(fd);
    return ntohs(address.sin_port);
}

TEST(RedisStorageTest, AnUnreachableServerFailsOnceAndFast) {
    Result<CacheSpec> spec =
        parseCacheSpec("redis://127.0.0.1:" + std::to_string(closedPort()) + "/0");
    ASSERT_TRUE(spec);
    RedisStorage storage(*spec);
    auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < 100; ++i) EXPECT_EQ(storage.get("k" + std::to_string(i)), std::nullopt);
    EXPECT_TRUE(storage.put("k", "v"));
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
    EXPECT_TRUE(storage.failed());
    CacheLevelStats stats = storage.stats();
    EXPECT_EQ(stats.errors + stats.timeouts, 1u) << "one failure, then the level is skipped";
    EXPECT_NE(storage.failure().find("cannot connect"), std::string::npos) << storage.failure();
    EXPECT_FALSE(storage.usage());
}

TEST(RedisStorageTest, AServerThatNeverAnswersTimesOut) {
    int fd = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ASSERT_EQ(::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address)), 0);
    ASSERT_EQ(::listen(fd, 4), 0);  // the kernel accepts; nobody ever answers
    socklen_t length = sizeof(address);
    ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length);
    Result<CacheSpec> spec = parseCacheSpec(
        "redis://127.0.0.1:" + std::to_string(ntohs(address.sin_port)) + "|operation-timeout=200");
    ASSERT_TRUE(spec);
    RedisStorage storage(*spec);
    auto start = std::chrono::steady_clock::now();
    EXPECT_EQ(storage.get("k"), std::nullopt);
    EXPECT_EQ(storage.get("j"), std::nullopt);
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
    EXPECT_TRUE(storage.failed());
    EXPECT_EQ(storage.stats().timeouts, 1u) << storage.failure();
    ::close(fd);
}

}  // namespace
}  // namespace varc::cache
