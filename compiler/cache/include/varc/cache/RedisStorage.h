// SPDX-License-Identifier: Apache-2.0
// RedisStorage: a shared cache level on a Redis server (through hiredis): MGET and SET of
// "<prefix><key>", with an optional expiry. It connects on first use with the connect timeout,
// and every command has the operation timeout, so a slow or dead server costs at most one
// timeout: any connection, I/O or protocol failure gives the level up for the rest of the run.
// A server that refuses a write (maxmemory reached, read-only replica) stops writes only; reads
// go on. SIGPIPE from a closed connection is blocked and discarded on the calling thread, so it
// never ends the process. One connection, guarded by a mutex, serves every thread.
#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <vector>

#include "varc/cache/CacheSpec.h"
#include "varc/cache/CacheStorage.h"

struct redisReply;

namespace varc::cache {

class RedisStorage final : public CacheStorage {
public:
    explicit RedisStorage(CacheSpec spec);
    ~RedisStorage() override;

    std::optional<std::string> get(std::string_view key) override;
    // One MGET per 512 keys.
    std::vector<std::optional<std::string>> getMany(const std::vector<std::string>& keys) override;
    Status put(std::string_view key, std::string_view value) override;
    Result<CacheUsage> usage() override;
    Result<uint64_t> clear() override;

private:
    struct Connection;
    // The connection, connecting first if needed; nullptr once the level failed. Mutex held.
    Connection* connectionLocked();
    // Runs a command (argv style); nullptr after a failure, which it has recorded. Mutex held.
    struct Reply;
    std::unique_ptr<Reply> commandLocked(const std::vector<std::string_view>& args);
    void failLocked(const std::string& what);
    // The value of one of MGET's replies, or nullopt (nil; anything else fails the level). Mutex
    // held.
    std::optional<std::string> valueLocked(const redisReply& reply);
    // Visits every key under the prefix (SCAN); stops at the first error |visit| returns.
    Status scanLocked(const std::function<Status(std::string_view)>& visit);
    Result<uint64_t> integerLocked(std::string_view command, std::string_view key);

    CacheSpec mSpec;
    std::mutex mMutex;
    std::unique_ptr<Connection> mConnection;
    bool mWritesRefused = false;
};

}  // namespace varc::cache
