// SPDX-License-Identifier: Apache-2.0
// CacheSpec: one cache level as the user names it (`--cache URL`, `VARC_CACHE`), ccache style:
//   file:DIR[|attribute...]                        a local folder
//   redis://[[USER:]PASSWORD@][HOST][:PORT][/DB][|attribute...]
//                                                  a Redis server (default 127.0.0.1:6379/0)
// Attributes: read-only; prefix=TEXT (Redis key prefix, default "varc:"); ttl=SECONDS (Redis
// expiry, default none); connect-timeout=MS (default 100); operation-timeout=MS (default 1000).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "varc/core/Result.h"

namespace varc::cache {

struct CacheSpec {
    enum class Kind { Directory, Redis };
    Kind kind = Kind::Directory;
    std::string url;        // as written, for messages, with any password replaced by "***"
    std::string directory;  // Directory
    std::string host = "127.0.0.1";
    uint16_t port = 6379;
    uint32_t database = 0;
    std::string username;  // Redis 6 ACL user ("" = the default user)
    std::string password;  // "" = no AUTH
    std::string prefix = "varc:";
    bool readOnly = false;
    uint32_t ttlSeconds = 0;  // 0 = entries never expire
    uint32_t connectTimeoutMs = 100;
    uint32_t operationTimeoutMs = 1000;
};

// Parses one URL. Errors quote the URL and say what is wrong, e.g.
// parseCacheSpec("redis://h:99999") -> "cache URL 'redis://h:99999': port 99999 is not 1-65535".
Result<CacheSpec> parseCacheSpec(std::string_view url);

// The local folder level `--cache-dir DIR` names: what parseCacheSpec("file:DIR") gives, built
// directly, so DIR is taken whole (a '|' in it is part of the folder's name, not an attribute).
CacheSpec directoryCacheSpec(std::string directory);

// Splits VARC_CACHE's value into URLs (separated by spaces, as ccache's remote_storage).
std::vector<std::string> splitCacheList(std::string_view list);

}  // namespace varc::cache
