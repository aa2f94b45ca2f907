// SPDX-License-Identifier: Apache-2.0
#include "varc/cache/RedisStorage.h"

#include <hiredis/hiredis.h>
#include <pthread.h>
#include <signal.h>

#include <algorithm>
#include <cerrno>
#include <ctime>

namespace varc::cache {

namespace {

timeval toTimeval(uint32_t milliseconds) {
    timeval tv{};
    tv.tv_sec = static_cast<time_t>(milliseconds / 1000);
    tv.tv_usec = static_cast<suseconds_t>((milliseconds % 1000) * 1000);
    return tv;
}

// Blocks SIGPIPE on this thread while alive; a SIGPIPE raised meanwhile (a write to a closed
// connection) is discarded instead of ending the process, and the thread's mask is restored.
class SigpipeGuard {
public:
    SigpipeGuard() {
        sigemptyset(&mPipe);
        sigaddset(&mPipe, SIGPIPE);
        sigset_t pending;
        sigpending(&pending);
        mWasPending = sigismember(&pending, SIGPIPE) == 1;
        pthread_sigmask(SIG_BLOCK, &mPipe, &mOld);
    }
    ~SigpipeGuard() {
        sigset_t pending;
        sigpending(&pending);
        if (!mWasPending && sigismember(&pending, SIGPIPE) == 1) {
            timespec zero{};
            while (sigtimedwait(&mPipe, nullptr, &zero) == -1 && errno == EINTR) {
            }
        }
        pthread_sigmask(SIG_SETMASK, &mOld, nullptr);
    }
    SigpipeGuard(const SigpipeGuard&) = delete;
    SigpipeGuard& operator=(const SigpipeGuard&) = delete;

private:
    sigset_t mPipe{}, mOld{};
    bool mWasPending = false;
};

bool isTimeout(const redisContext& context) {
    return context.err == REDIS_ERR_IO &&
           (errno == EAGAIN || errno == EWOULDBLOCK || errno == ETIMEDOUT ||
            std::string_view(context.errstr).find("timed out") != std::string_view::npos);
}

}  // namespace

struct RedisStorage::Connection {
    redisContext* context = nullptr;
    ~Connection() {
        if (context) redisFree(context);
    }
};

struct RedisStorage::Reply {
    redisReply* reply = nullptr;
    ~Reply() {
        if (reply) freeReplyObject(reply);
    }
};

RedisStorage::RedisStorage(CacheSpec spec)
    : CacheStorage(spec.url, spec.readOnly), mSpec(std::move(spec)) {}

RedisStorage::~RedisStorage() = default;

void RedisStorage::failLocked(const std::string& what) {
    const redisContext* context = mConnection ? mConnection->context : nullptr;
    bool timeout = context && isTimeout(*context);
    std::string reason = what;
    if (context && context->err) reason += std::string(": ") + context->errstr;
    if (timeout) reason += " (timeout)";
    noteError(reason, timeout, /*fatal=*/true);
    mConnection.reset();
}

RedisStorage::Connection* RedisStorage::connectionLocked() {
    if (failed()) return nullptr;
    if (mConnection) return mConnection.get();
    mConnection = std::make_unique<Connection>();
    mConnection->context =
        redisConnectWithTimeout(mSpec.host.c_str(), mSpec.port, toTimeval(mSpec.connectTimeoutMs));
    if (!mConnection->context || mConnection->context->err) {
        failLocked("cannot connect to " + mSpec.host + ":" + std::to_string(mSpec.port));
        return nullptr;
    }
    if (redisSetTimeout(mConnection->context, toTimeval(mSpec.operationTimeoutMs)) != REDIS_OK) {
        failLocked("cannot set the operation timeout");
        return nullptr;
    }
    if (!mSpec.password.empty()) {
        std::unique_ptr<Reply> auth = mSpec.username.empty()
                                          ? commandLocked({"AUTH", mSpec.password})
                                          : commandLocked({"AUTH", mSpec.username, mSpec.password});
        if (!auth) return nullptr;
        if (auth->reply->type != REDIS_REPLY_STATUS) {
            const redisReply& r = *auth->reply;
            failLocked("AUTH refused" + (r.type == REDIS_REPLY_ERROR
                                             ? " (" + std::string(r.str, r.len) + ")"
                                             : std::string()));
            return nullptr;
        }
    }
    if (mSpec.database != 0) {
        std::string db = std::to_string(mSpec.database);
        std::unique_ptr<Reply> selected = commandLocked({"SELECT", db});
        if (!selected) return nullptr;
        if (selected->reply->type != REDIS_REPLY_STATUS) {
            failLocked("SELECT " + db + " refused");
            return nullptr;
        }
    }
    return mConnection.get();
}

std::unique_ptr<RedisStorage::Reply> RedisStorage::commandLocked(
    const std::vector<std::string_view>& args) {
    if (!mConnection || failed()) return nullptr;
    std::vector<const char*> argv;
    std::vector<size_t> lengths;
    for (std::string_view arg : args) {
        argv.push_back(arg.data());
        lengths.push_back(arg.size());
    }
    auto reply = std::make_unique<Reply>();
    {
        SigpipeGuard guard;
        errno = 0;
        reply->reply = static_cast<redisReply*>(redisCommandArgv(
            mConnection->context, static_cast<int>(argv.size()), argv.data(), lengths.data()));
    }
    if (!reply->reply) {
        failLocked(std::string(args[0]) + " failed");
        return nullptr;
    }
    return reply;
}

std::optional<std::string> RedisStorage::valueLocked(const redisReply& r) {
    if (r.type == REDIS_REPLY_NIL) return std::nullopt;
    if (r.type != REDIS_REPLY_STRING) {
        failLocked("MGET answered " + (r.type == REDIS_REPLY_ERROR ? std::string(r.str, r.len)
                                                                   : std::string("no string")));
        return std::nullopt;
    }
    countRead(r.len);
    return std::string(r.str, r.len);
}

std::optional<std::string> RedisStorage::get(std::string_view key) {
    return getMany({std::string(key)})[0];
}

std::vector<std::optional<std::string>> RedisStorage::getMany(
    const std::vector<std::string>& keys) {
    // MGET, not pipelined GETs: hiredis 0.14 moves its read buffer after every reply, which
    // makes a long pipeline of large values quadratic; one array reply is read once.
    constexpr size_t kBatch = 512;
    std::vector<std::optional<std::string>> values(keys.size());
    std::lock_guard<std::mutex> lock(mMutex);
    for (size_t first = 0; first < keys.size(); first += kBatch) {
        if (!connectionLocked()) break;
        const size_t count = std::min(kBatch, keys.size() - first);
        std::vector<std::string> names;
        names.reserve(count);
        std::vector<std::string_view> args = {"MGET"};
        for (size_t k = first; k < first + count; ++k) names.push_back(mSpec.prefix + keys[k]);
        args.insert(args.end(), names.begin(), names.end());
        std::unique_ptr<Reply> reply = commandLocked(args);
        if (!reply) break;
        const redisReply& r = *reply->reply;
        if (r.type != REDIS_REPLY_ARRAY || r.elements != count) {
            failLocked("MGET answered " + (r.type == REDIS_REPLY_ERROR ? std::string(r.str, r.len)
                                                                       : std::string("nonsense")));
            break;
        }
        for (size_t k = 0; k < count && !failed(); ++k)
            values[first + k] = valueLocked(*r.element[k]);
    }
    return values;
}

Status RedisStorage::put(std::string_view key, std::string_view value) {
    std::lock_guard<std::mutex> lock(mMutex);
    if (mWritesRefused || readOnly() || !connectionLocked()) return Ok{};
    std::string name = mSpec.prefix + std::string(key);
    std::string ttl = std::to_string(mSpec.ttlSeconds);
    std::unique_ptr<Reply> reply = mSpec.ttlSeconds ? commandLocked({"SET", name, value, "EX", ttl})
                                                    : commandLocked({"SET", name, value});
    if (!reply) return Ok{};
    const redisReply& r = *reply->reply;
    if (r.type == REDIS_REPLY_ERROR) {
        // The server is up but will not store (maxmemory, a read-only replica): keep reading.
        mWritesRefused = true;
        noteError("SET answered " + std::string(r.str, r.len), false, /*fatal=*/false);
    } else if (r.type != REDIS_REPLY_STATUS) {
        failLocked("SET answered no status");
    } else {
        countWrite(value.size());
    }
    return Ok{};
}

Status RedisStorage::scanLocked(const std::function<Status(std::string_view)>& visit) {
    std::string cursor = "0", pattern = mSpec.prefix + "*";
    auto lost = [&] { return makeError(ErrorCode::IoError, name() + ": " + failure()); };
    do {
        if (!connectionLocked()) return lost();
        std::unique_ptr<Reply> page =
            commandLocked({"SCAN", cursor, "MATCH", pattern, "COUNT", "1000"});
        if (!page) return lost();
        const redisReply& r = *page->reply;
        if (r.type != REDIS_REPLY_ARRAY || r.elements != 2 ||
            r.element[0]->type != REDIS_REPLY_STRING || r.element[1]->type != REDIS_REPLY_ARRAY)
            return makeError(ErrorCode::InvalidInput, name() + ": SCAN answered nonsense");
        cursor.assign(r.element[0]->str, r.element[0]->len);
        for (size_t i = 0; i < r.element[1]->elements; ++i) {
            const redisReply& key = *r.element[1]->element[i];
            if (key.type != REDIS_REPLY_STRING) continue;
            if (Status visited = visit(std::string_view(key.str, key.len)); !visited)
                return visited;
        }
    } while (cursor != "0");
    return Ok{};
}

// The integer a one-key command (STRLEN, DEL) answers, or an error once the level failed.
Result<uint64_t> RedisStorage::integerLocked(std::string_view command, std::string_view key) {
    std::unique_ptr<Reply> reply = commandLocked({command, key});
    if (!reply) return makeError(ErrorCode::IoError, name() + ": " + failure());
    if (reply->reply->type != REDIS_REPLY_INTEGER || reply->reply->integer < 0) return uint64_t{0};
    return static_cast<uint64_t>(reply->reply->integer);
}

Result<CacheUsage> RedisStorage::usage() {
    std::lock_guard<std::mutex> lock(mMutex);
    CacheUsage usage;
    Status scanned = scanLocked([&](std::string_view key) -> Status {
        Result<uint64_t> bytes = integerLocked("STRLEN", key);
        if (!bytes) return bytes.error();
        ++usage.entries;
        usage.bytes += *bytes;
        return Ok{};
    });
    if (!scanned) return scanned.error();
    return usage;
}

Result<uint64_t> RedisStorage::clear() {
    std::lock_guard<std::mutex> lock(mMutex);
    uint64_t removed = 0;
    Status scanned = scanLocked([&](std::string_view key) -> Status {
        Result<uint64_t> deleted = integerLocked("DEL", key);
        if (!deleted) return deleted.error();
        removed += *deleted;
        return Ok{};
    });
    if (!scanned) return scanned.error();
    return removed;
}

}  // namespace varc::cache
