// SPDX-License-Identifier: Apache-2.0
// ShardPlan: parsing --shard K/N and the balanced, deterministic assignment of programs.
#include "varc/build/ShardPlan.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

namespace varc::compiler {
namespace {

TEST(ShardPlan, ParsesKOfN) {
    std::optional<ShardSpec> spec = parseShardSpec("2/5");
    ASSERT_TRUE(spec);
    EXPECT_EQ(spec->index, 2u);
    EXPECT_EQ(spec->count, 5u);
    EXPECT_EQ(spec->text(), "2/5");
    EXPECT_FALSE(spec->whole());
    EXPECT_TRUE(parseShardSpec("1/1")->whole());
    for (const char* bad : {"0/2", "3/2", "2", "/2", "2/", "a/b", "1/4097", "1/2x", " 1/2", "-1/2"})
        EXPECT_FALSE(parseShardSpec(bad)) << bad;
}

TEST(ShardPlan, OneShardTakesEverything) {
    EXPECT_EQ(assignShards({5, 1, 9}, 1), (std::vector<uint32_t>{0, 0, 0}));
}

TEST(ShardPlan, LongestFirstToTheLeastLoadedShard) {
    // 9 -> shard 0, 8 -> 1, 5 -> 1 (load 8 < 9), 4 -> 0 (9 < 13), 1 -> 0 (13 = 13: the lower).
    EXPECT_EQ(assignShards({4, 9, 1, 8, 5}, 2), (std::vector<uint32_t>{0, 0, 0, 1, 1}));
    // Equal costs go round in item order.
    EXPECT_EQ(assignShards({3, 3, 3, 3}, 3), (std::vector<uint32_t>{0, 1, 2, 0}));
}

TEST(ShardPlan, BalancesRealisticCostsAndUsesEveryShard) {
    std::mt19937 random(7);
    std::uniform_int_distribution<uint64_t> size(500, 60000);
    std::vector<uint64_t> costs(400);
    for (uint64_t& cost : costs) cost = size(random);
    for (uint32_t count : {2u, 3u, 8u}) {
        std::vector<uint32_t> shards = assignShards(costs, count);
        std::vector<uint64_t> load(count, 0);
        for (size_t i = 0; i < costs.size(); ++i) {
            ASSERT_LT(shards[i], count);
            load[shards[i]] += costs[i];
        }
        uint64_t most = *std::max_element(load.begin(), load.end());
        uint64_t least = *std::min_element(load.begin(), load.end());
        // Longest-first greedy leaves the shards within the largest single cost of each other.
        EXPECT_LE(most - least, *std::max_element(costs.begin(), costs.end())) << count;
        EXPECT_GT(least, 0u);
        EXPECT_EQ(assignShards(costs, count), shards);  // deterministic
    }
}

}  // namespace
}  // namespace varc::compiler
