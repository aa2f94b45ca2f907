// SPDX-License-Identifier: Apache-2.0
#include "varc/cache/CacheSpec.h"

#include <algorithm>
#include <charconv>
#include <optional>
#include <utility>

namespace varc::cache {

namespace {

// |text| as a number in [min, max], or nullopt.
std::optional<uint64_t> number(std::string_view text, uint64_t min, uint64_t max) {
    uint64_t value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || text.empty()) return {};
    if (value < min || value > max) return {};
    return value;
}

std::vector<std::string_view> split(std::string_view text, char separator) {
    std::vector<std::string_view> parts;
    size_t start = 0;
    while (true) {
        size_t end = text.find(separator, start);
        parts.push_back(text.substr(start, end == std::string_view::npos ? end : end - start));
        if (end == std::string_view::npos) return parts;
        start = end + 1;
    }
}

// Parses "[HOST][:PORT][/DB]" into |spec|; "" or the reason.
std::string parseRedisAddress(std::string_view address, CacheSpec& spec) {
    if (size_t slash = address.find('/'); slash != std::string_view::npos) {
        std::string_view db = address.substr(slash + 1);
        auto value = number(db, 0, 1u << 20);
        if (!value) return "database '" + std::string(db) + "' is not a number";
        spec.database = static_cast<uint32_t>(*value);
        address = address.substr(0, slash);
    }
    if (size_t colon = address.rfind(':'); colon != std::string_view::npos) {
        std::string_view port = address.substr(colon + 1);
        auto value = number(port, 1, 65535);
        if (!value) return "port " + std::string(port) + " is not 1-65535";
        spec.port = static_cast<uint16_t>(*value);
        address = address.substr(0, colon);
    }
    if (!address.empty()) spec.host = address;
    return "";
}

// Applies one "name[=value]" attribute; "" or the reason.
std::string applyAttribute(std::string_view attribute, CacheSpec& spec) {
    size_t equals = attribute.find('=');
    std::string_view name = attribute.substr(0, equals);
    std::string_view value =
        equals == std::string_view::npos ? std::string_view() : attribute.substr(equals + 1);
    auto milliseconds = [&](uint32_t& out) -> std::string {
        auto ms = number(value, 1, 600000);
        if (!ms) return std::string(name) + " '" + std::string(value) + "' is not 1-600000 ms";
        out = static_cast<uint32_t>(*ms);
        return "";
    };
    if (name == "read-only" && equals == std::string_view::npos) {
        spec.readOnly = true;
        return "";
    }
    if (name == "prefix" && spec.kind == CacheSpec::Kind::Redis) {
        spec.prefix = value;
        return "";
    }
    if (name == "ttl" && spec.kind == CacheSpec::Kind::Redis) {
        auto seconds = number(value, 1, 1u << 31);
        if (!seconds) return "ttl '" + std::string(value) + "' is not a number of seconds";
        spec.ttlSeconds = static_cast<uint32_t>(*seconds);
        return "";
    }
    if (name == "connect-timeout" && spec.kind == CacheSpec::Kind::Redis)
        return milliseconds(spec.connectTimeoutMs);
    if (name == "operation-timeout" && spec.kind == CacheSpec::Kind::Redis)
        return milliseconds(spec.operationTimeoutMs);
    return "unknown attribute '" + std::string(attribute) +
           "' (known: read-only; for redis: prefix=, ttl=, connect-timeout=, operation-timeout=)";
}

// Takes "[[USER:]PASSWORD@]" off the front of a Redis |address| into |spec|, and returns the URL
// to print instead of |url|: the password replaced by "***".
std::string takeCredentials(std::string_view url, std::string_view& address, CacheSpec& spec) {
    size_t at = address.rfind('@');
    if (at == std::string_view::npos) return std::string(url);
    std::string_view credentials = address.substr(0, at);
    size_t colon = credentials.find(':');
    std::string masked = "***";
    if (colon != std::string_view::npos) {
        spec.username = credentials.substr(0, colon);
        masked = spec.username + ":***";
    }
    spec.password = colon == std::string_view::npos ? credentials : credentials.substr(colon + 1);
    address = address.substr(at + 1);
    size_t start = std::string_view("redis://").size();
    return std::string(url.substr(0, start)) + masked + "@" +
           std::string(url.substr(start + at + 1));
}

}  // namespace

Result<CacheSpec> parseCacheSpec(std::string_view url) {
    CacheSpec spec;
    std::vector<std::string_view> parts = split(url, '|');
    std::string_view location = parts[0];
    std::string_view address = location.substr(std::min<size_t>(location.size(), 8));
    spec.url = location.substr(0, 8) == "redis://" ? takeCredentials(url, address, spec)
                                                   : std::string(url);
    auto fail = [&](const std::string& reason) {
        return makeError(ErrorCode::InvalidInput, "cache URL '" + spec.url + "': " + reason);
    };
    if (location.substr(0, 5) == "file:") {
        spec.directory = location.substr(5);
        if (spec.directory.empty()) return fail("no folder after 'file:'");
    } else if (location.substr(0, 8) == "redis://") {
        spec.kind = CacheSpec::Kind::Redis;
        if (std::string reason = parseRedisAddress(address, spec); !reason.empty())
            return fail(reason);
    } else {
        return fail("expected file:DIR or redis://HOST[:PORT][/DB]");
    }
    for (size_t i = 1; i < parts.size(); ++i) {
        if (std::string reason = applyAttribute(parts[i], spec); !reason.empty())
            return fail(reason);
    }
    return spec;
}

CacheSpec directoryCacheSpec(std::string directory) {
    CacheSpec spec;
    spec.url = "file:" + directory;
    spec.directory = std::move(directory);
    return spec;
}

std::vector<std::string> splitCacheList(std::string_view list) {
    std::vector<std::string> urls;
    for (std::string_view part : split(list, ' ')) {
        if (!part.empty()) urls.emplace_back(part);
    }
    return urls;
}

}  // namespace varc::cache
