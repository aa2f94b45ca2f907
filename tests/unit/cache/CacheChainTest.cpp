// SPDX-License-Identifier: Apache-2.0
// CacheChain: levels in order, write-back of shared hits, damaged values are misses, and a
// failed level is skipped with one warning while the build goes on.
#include <gtest/gtest.h>

#include <map>

#include "varc/cache/CacheChain.h"

namespace varc::cache {
namespace {

// An in-memory level that can be told to fail, as a remote that goes away does.
class MemoryStorage final : public CacheStorage {
public:
    MemoryStorage(std::string name, bool readOnly = false)
        : CacheStorage(std::move(name), readOnly) {}
    std::optional<std::string> get(std::string_view key) override {
        ++gets;
        if (breakOnUse) noteError("connection lost", false, true);
        if (failed()) return std::nullopt;
        auto it = values.find(std::string(key));
        if (it == values.end()) return std::nullopt;
        countRead(it->second.size());
        return it->second;
    }
    Status put(std::string_view key, std::string_view value) override {
        if (failed()) return Ok{};
        values[std::string(key)] = value;
        if (mirror) (*mirror)[std::string(key)] = value;
        countWrite(value.size());
        return Ok{};
    }
    Status putMany(const std::vector<CacheEntry>& entries) override {
        ++putManyCalls;
        return CacheStorage::putMany(entries);
    }
    Result<CacheUsage> usage() override { return CacheUsage{values.size(), 0}; }
    Result<uint64_t> clear() override {
        uint64_t n = values.size();
        values.clear();
        return n;
    }
    std::map<std::string, std::string> values;
    bool breakOnUse = false;
    int gets = 0;
    int putManyCalls = 0;
    std::map<std::string, std::string>* mirror = nullptr;  // also gets every put
};

struct Chain {
    MemoryStorage* local;
    MemoryStorage* shared;
    CacheChain chain;
};

Chain makeChain(bool localReadOnly = false) {
    auto local = std::make_unique<MemoryStorage>("file:local", localReadOnly);
    auto shared = std::make_unique<MemoryStorage>("redis://shared");
    Chain result{local.get(), shared.get(), CacheChain({})};
    std::vector<std::unique_ptr<CacheStorage>> levels;
    levels.push_back(std::move(local));
    levels.push_back(std::move(shared));
    result.chain = CacheChain(std::move(levels));
    return result;
}

auto acceptAll = [](std::string_view) { return true; };

TEST(CacheChainTest, APutReachesEveryWritableLevel) {
    Chain c = makeChain(/*localReadOnly=*/true);
    ASSERT_TRUE(c.chain.put("k", "value"));
    EXPECT_EQ(c.local->values.count("k"), 0u) << "a read-only level is never written";
    EXPECT_EQ(c.shared->values["k"], "value");
}

TEST(CacheChainTest, ASharedHitIsWrittenBackToTheLocalLevel) {
    Chain c = makeChain();
    c.shared->values["k"] = "value";
    EXPECT_EQ(c.chain.get("k", acceptAll), "value");
    EXPECT_EQ(c.local->values.count("k"), 0u) << "write-backs wait for the flush";
    c.chain.flushWriteBacks();
    EXPECT_EQ(c.local->values["k"], "value");
    std::vector<CacheLevelStats> stats = c.chain.stats();
    EXPECT_EQ(stats[0].misses, 1u);
    EXPECT_EQ(stats[1].hits, 1u);
    EXPECT_EQ(stats[1].bytesRead, 5u);
    EXPECT_EQ(stats[0].bytesWritten, 5u);
    // The next get is served locally.
    EXPECT_EQ(c.chain.get("k", acceptAll), "value");
    EXPECT_EQ(c.chain.stats()[0].hits, 1u);
    EXPECT_EQ(c.shared->gets, 1);
}

TEST(CacheChainTest, ADamagedValueIsAMissAndTheNextLevelIsTried) {
    Chain c = makeChain();
    c.local->values["k"] = "garbage";
    c.shared->values["k"] = "value";
    auto accept = [](std::string_view v) { return v == "value"; };
    EXPECT_EQ(c.chain.get("k", accept), "value");
    EXPECT_EQ(c.chain.stats()[0].damaged, 1u);
    c.chain.flushWriteBacks();
    EXPECT_EQ(c.local->values["k"], "value") << "the sound value replaces the damaged one";
    c.shared->values["j"] = "garbage";
    EXPECT_EQ(c.chain.get("j", accept), std::nullopt);
    c.chain.flushWriteBacks();
    EXPECT_EQ(c.chain.stats()[1].damaged, 1u);
    EXPECT_EQ(c.local->values.count("j"), 0u) << "a damaged value is never written back";
}

TEST(CacheChainTest, WriteBacksAreWrittenInOneBatchPerLevel) {
    Chain c = makeChain();
    std::vector<std::string> keys;
    for (int i = 0; i < 40; ++i) {
        keys.push_back("k" + std::to_string(i));
        c.shared->values[keys.back()] = "v" + std::to_string(i);
    }
    // Lookups in several calls, as a build makes them chunk by chunk.
    c.chain.getMany({keys.begin(), keys.begin() + 20}, [](size_t, std::string_view) { return true; });
    c.chain.getMany({keys.begin() + 20, keys.end()}, [](size_t, std::string_view) { return true; });
    EXPECT_TRUE(c.local->values.empty());
    c.chain.flushWriteBacks();
    EXPECT_EQ(c.local->putManyCalls, 1);
    EXPECT_EQ(c.local->values.size(), 40u);
    EXPECT_EQ(c.local->values["k39"], "v39");
    c.chain.flushWriteBacks();
    EXPECT_EQ(c.local->putManyCalls, 1) << "nothing left to write";
}

TEST(CacheChainTest, TheChainWritesBackWhatIsLeftWhenItGoes) {
    std::map<std::string, std::string> written;  // outlives the chain and its levels
    {
        Chain c = makeChain();
        c.local->mirror = &written;
        c.shared->values["k"] = "value";
        EXPECT_EQ(c.chain.get("k", acceptAll), "value");
        EXPECT_TRUE(written.empty());
    }
    EXPECT_EQ(written["k"], "value");
}

TEST(CacheChainTest, AFailedLevelIsSkippedWithOneWarning) {
    Chain c = makeChain();
    c.shared->breakOnUse = true;
    for (int i = 0; i < 5; ++i)
        EXPECT_EQ(c.chain.get("k" + std::to_string(i), acceptAll), std::nullopt);
    EXPECT_EQ(c.shared->gets, 1) << "a failed level is not asked again";
    ASSERT_TRUE(c.chain.put("k", "v"));
    EXPECT_EQ(c.local->values["k"], "v") << "the local level goes on";
    std::vector<std::string> warnings = c.chain.warnings();
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("redis://shared failed (connection lost)"), std::string::npos)
        << warnings[0];
    EXPECT_TRUE(c.chain.stats()[1].failed);
    EXPECT_EQ(c.chain.stats()[1].errors, 1u);
}

}  // namespace
}  // namespace varc::cache
