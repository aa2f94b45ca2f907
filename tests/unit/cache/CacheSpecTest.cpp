// SPDX-License-Identifier: Apache-2.0
// CacheSpec: the URLs `--cache` and VARC_CACHE accept, their defaults and their errors.
#include <gtest/gtest.h>

#include "varc/cache/CacheSpec.h"

namespace varc::cache {
namespace {

TEST(CacheSpecTest, AFileUrlNamesAFolder) {
    Result<CacheSpec> spec = parseCacheSpec("file:/tmp/c|read-only");
    ASSERT_TRUE(spec) << spec.error().detail;
    EXPECT_EQ(spec->kind, CacheSpec::Kind::Directory);
    EXPECT_EQ(spec->directory, "/tmp/c");
    EXPECT_TRUE(spec->readOnly);
    EXPECT_EQ(spec->url, "file:/tmp/c|read-only");
}

TEST(CacheSpecTest, ARedisUrlHasShortDefaults) {
    Result<CacheSpec> spec = parseCacheSpec("redis://");
    ASSERT_TRUE(spec) << spec.error().detail;
    EXPECT_EQ(spec->kind, CacheSpec::Kind::Redis);
    EXPECT_EQ(spec->host, "127.0.0.1");
    EXPECT_EQ(spec->port, 6379);
    EXPECT_EQ(spec->database, 0u);
    EXPECT_EQ(spec->prefix, "varc:");
    EXPECT_FALSE(spec->readOnly);
    EXPECT_EQ(spec->ttlSeconds, 0u);
    EXPECT_EQ(spec->connectTimeoutMs, 100u);
    EXPECT_EQ(spec->operationTimeoutMs, 1000u);
}

TEST(CacheSpecTest, EveryRedisPartAndAttributeIsRead) {
    Result<CacheSpec> spec = parseCacheSpec(
        "redis://cache.example:7000/3|prefix=ci:|ttl=86400|read-only|connect-timeout=50|"
        "operation-timeout=250");
    ASSERT_TRUE(spec) << spec.error().detail;
    EXPECT_EQ(spec->host, "cache.example");
    EXPECT_EQ(spec->port, 7000);
    EXPECT_EQ(spec->database, 3u);
    EXPECT_EQ(spec->prefix, "ci:");
    EXPECT_EQ(spec->ttlSeconds, 86400u);
    EXPECT_TRUE(spec->readOnly);
    EXPECT_EQ(spec->connectTimeoutMs, 50u);
    EXPECT_EQ(spec->operationTimeoutMs, 250u);
}

TEST(CacheSpecTest, CredentialsAreReadAndNeverPrinted) {
    Result<CacheSpec> spec = parseCacheSpec("redis://ci:s3cr@t@cache.example:7000/2|read-only");
    ASSERT_TRUE(spec) << spec.error().detail;
    EXPECT_EQ(spec->username, "ci");
    EXPECT_EQ(spec->password, "s3cr@t");
    EXPECT_EQ(spec->host, "cache.example");
    EXPECT_EQ(spec->port, 7000);
    EXPECT_EQ(spec->url, "redis://ci:***@cache.example:7000/2|read-only");
    Result<CacheSpec> password = parseCacheSpec("redis://hunter2@h");
    ASSERT_TRUE(password);
    EXPECT_EQ(password->username, "");
    EXPECT_EQ(password->password, "hunter2");
    EXPECT_EQ(password->url, "redis://***@h");
    Result<CacheSpec> bad = parseCacheSpec("redis://hunter2@h:0");
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().detail.find("hunter2"), std::string::npos) << bad.error().detail;
}

TEST(CacheSpecTest, BadUrlsAreErrorsThatQuoteThem) {
    const std::pair<const char*, const char*> cases[] = {
        {"/tmp/c", "expected file:DIR or redis://"},
        {"file:", "no folder"},
        {"redis://h:0", "port 0 is not 1-65535"},
        {"redis://h:99999", "port 99999 is not 1-65535"},
        {"redis://h:x", "port x is not"},
        {"redis://h/db", "database 'db' is not a number"},
        {"redis://h|ttl=soon", "ttl 'soon'"},
        {"redis://h|operation-timeout=0", "operation-timeout '0'"},
        {"redis://h|colour=blue", "unknown attribute 'colour=blue'"},
        {"file:/c|ttl=5", "unknown attribute 'ttl=5'"},
        {"redis://h|read-only=yes", "unknown attribute 'read-only=yes'"},
    };
    for (const auto& [url, reason] : cases) {
        Result<CacheSpec> spec = parseCacheSpec(url);
        ASSERT_FALSE(spec) << url;
        EXPECT_NE(spec.error().detail.find("cache URL '" + std::string(url) + "'"),
                  std::string::npos)
            << spec.error().detail;
        EXPECT_NE(spec.error().detail.find(reason), std::string::npos) << spec.error().detail;
    }
}

TEST(CacheSpecTest, AFolderLevelIsWhatItsFileUrlParsesTo) {
    CacheSpec built = directoryCacheSpec("/var/cache/varc");
    CacheSpec parsed = *parseCacheSpec("file:/var/cache/varc");
    EXPECT_EQ(built.kind, parsed.kind);
    EXPECT_EQ(built.url, parsed.url);
    EXPECT_EQ(built.directory, parsed.directory);
    EXPECT_EQ(built.readOnly, parsed.readOnly);
    // The folder's name is taken whole: '|' is part of it, not an attribute.
    CacheSpec piped = directoryCacheSpec("odd|read-only");
    EXPECT_EQ(piped.kind, CacheSpec::Kind::Directory);
    EXPECT_EQ(piped.directory, "odd|read-only");
    EXPECT_FALSE(piped.readOnly);
    EXPECT_EQ(piped.url, "file:odd|read-only");
}

TEST(CacheSpecTest, TheEnvironmentListSplitsOnSpaces) {
    EXPECT_EQ(splitCacheList(" file:/a  redis://h:1/2 "),
              (std::vector<std::string>{"file:/a", "redis://h:1/2"}));
    EXPECT_TRUE(splitCacheList("").empty());
}

}  // namespace
}  // namespace varc::cache
