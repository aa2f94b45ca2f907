// SPDX-License-Identifier: Apache-2.0
// RedisStorage: an unreachable or silent remote fails fast, once, and never throws or stalls;
// against a redis-server of its own (skipped, saying so, when none is installed): values
// round-trip in batches, prefix, read-only, stats and clear, a full server refuses writes only.
// The builds against Redis are in tests/cache.
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>

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

// A redis-server on a free loopback port for one test, stopped (by its pid) at the end.
class RedisServer {
public:
    explicit RedisServer(const std::string& options = "") {
        if (std::system("command -v redis-server >/dev/null 2>&1") != 0) return;
        mPort = closedPort();
        mDir = std::filesystem::temp_directory_path() /
               ("varc-redis-test-" + std::to_string(::getpid()) + "-" + std::to_string(mPort));
        std::filesystem::create_directories(mDir);
        std::string start = "redis-server --bind 127.0.0.1 --port " + std::to_string(mPort) +
                            " --save '' --appendonly no --daemonize yes --pidfile " + pidFile() +
                            " --logfile " + (mDir / "log").string() + " --dir " + mDir.string() +
                            " " + options;
        std::string wait = "for i in $(seq 50); do redis-cli -p " + std::to_string(mPort) +
                           " ping >/dev/null 2>&1 && exit 0; sleep 0.1; done; exit 1";
        mRunning = std::system(start.c_str()) == 0 && std::system(wait.c_str()) == 0;
    }
    ~RedisServer() {
        if (!mDir.empty()) {
            (void)std::system(("kill $(cat " + pidFile() + ") 2>/dev/null").c_str());
            std::error_code ignored;
            std::filesystem::remove_all(mDir, ignored);
        }
    }
    bool running() const { return mRunning; }
    std::string url(const std::string& attributes = "") const {
        return "redis://127.0.0.1:" + std::to_string(mPort) + "/0" + attributes;
    }

private:
    std::string pidFile() const { return (mDir / "pid").string(); }
    uint16_t mPort = 0;
    std::filesystem::path mDir;
    bool mRunning = false;
};

#define VARC_REQUIRE_REDIS(server)                                              \
    if (std::system("command -v redis-server >/dev/null 2>&1") != 0)            \
        GTEST_SKIP() << "redis-server not installed (scripts/install-deps.sh)"; \
    ASSERT_TRUE((server).running()) << "redis-server did not start"

TEST(RedisStorageTest, ValuesRoundTripInBatchesUnderThePrefix) {
    RedisServer server;
    VARC_REQUIRE_REDIS(server);
    RedisStorage storage(*parseCacheSpec(server.url("|prefix=t:")));
    ASSERT_TRUE(storage.put("a.program", std::string("bytes\0with nul", 14)));
    ASSERT_TRUE(storage.put("b.source", "text"));
    std::vector<std::string> keys;
    for (int i = 0; i < 1100; ++i)
        keys.push_back(i == 7 ? "a.program" : "missing" + std::to_string(i));
    keys.push_back("b.source");
    std::vector<std::optional<std::string>> values = storage.getMany(keys);
    ASSERT_EQ(values.size(), keys.size());
    EXPECT_EQ(values[7], std::string("bytes\0with nul", 14));
    EXPECT_EQ(values.back(), "text");
    EXPECT_EQ(std::count(values.begin(), values.end(), std::nullopt), 1099);
    EXPECT_FALSE(storage.failed()) << storage.failure();
    CacheLevelStats stats = storage.stats();
    EXPECT_EQ(stats.bytesRead, 18u);
    EXPECT_EQ(stats.bytesWritten, 18u);
    Result<CacheUsage> usage = storage.usage();
    ASSERT_TRUE(usage) << usage.error().detail;
    EXPECT_EQ(usage->entries, 2u);
    EXPECT_EQ(usage->bytes, 18u);
    RedisStorage other(*parseCacheSpec(server.url("|prefix=u:")));
    ASSERT_TRUE(other.put("c.program", "other"));
    Result<uint64_t> removed = storage.clear();
    ASSERT_TRUE(removed) << removed.error().detail;
    EXPECT_EQ(*removed, 2u);
    EXPECT_EQ(other.get("c.program"), "other") << "clear removes only its own prefix";
}

TEST(RedisStorageTest, APasswordIsSentAndAWrongOneFailsTheLevel) {
    RedisServer server("--requirepass s3cret");
    VARC_REQUIRE_REDIS(server);
    const std::string port = server.url().substr(18);  // "PORT/0" after "redis://127.0.0.1:"
    RedisStorage good(*parseCacheSpec("redis://s3cret@127.0.0.1:" + port));
    ASSERT_TRUE(good.put("k", "v"));
    EXPECT_EQ(good.get("k"), "v");
    EXPECT_FALSE(good.failed()) << good.failure();
    RedisStorage wrong(*parseCacheSpec("redis://wrong@127.0.0.1:" + port));
    EXPECT_EQ(wrong.get("k"), std::nullopt);
    EXPECT_TRUE(wrong.failed());
    EXPECT_NE(wrong.failure().find("AUTH"), std::string::npos) << wrong.failure();
    EXPECT_EQ(wrong.name().find("wrong"), std::string::npos) << "the password is never printed";
}

TEST(RedisStorageTest, AReadOnlyLevelNeverWrites) {
    RedisServer server;
    VARC_REQUIRE_REDIS(server);
    RedisStorage readOnly(*parseCacheSpec(server.url("|read-only")));
    ASSERT_TRUE(readOnly.put("k", "v"));
    RedisStorage reader(*parseCacheSpec(server.url()));
    EXPECT_EQ(reader.get("k"), std::nullopt);
    EXPECT_EQ(readOnly.stats().writes, 0u);
}

TEST(RedisStorageTest, AFullServerRefusesWritesOnlyAndOnce) {
    RedisServer server("--maxmemory 1mb --maxmemory-policy noeviction");
    VARC_REQUIRE_REDIS(server);
    RedisStorage storage(*parseCacheSpec(server.url()));
    const std::string big(64 * 1024, 'x');
    ASSERT_TRUE(storage.put("first", "kept"));
    for (int i = 0; i < 64 && storage.failure().empty(); ++i)
        ASSERT_TRUE(storage.put("big" + std::to_string(i), big));
    EXPECT_NE(storage.failure().find("OOM"), std::string::npos) << storage.failure();
    EXPECT_FALSE(storage.failed()) << "a full server still serves reads";
    EXPECT_EQ(storage.stats().errors, 1u);
    EXPECT_EQ(storage.get("first"), "kept");
}

}  // namespace
}  // namespace varc::cache
