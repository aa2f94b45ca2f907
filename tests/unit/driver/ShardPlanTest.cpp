// SPDX-License-Identifier: Apache-2.0
// ShardPlan: parsing --shard K/N, cutting the plan into units and the balanced, deterministic
// assignment of units to shards.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "varc/driver/ShardPlan.h"

namespace varc::driver {
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

// Jobs like a real build's: many small passes, a few with hundreds of variants, one huge one.
std::vector<ShardJobSize> realisticJobs() {
    std::mt19937 random(11);
    std::uniform_int_distribution<size_t> variants(1, 40), stages(1, 3);
    std::uniform_int_distribution<uint64_t> bytes(2000, 90000);
    std::vector<ShardJobSize> jobs;
    for (int i = 0; i < 300; ++i) jobs.push_back({variants(random), stages(random), bytes(random)});
    jobs.push_back({700, 2, 50000});
    jobs.push_back({0, 2, 1000});  // nothing to build
    jobs.push_back({10000, 2, 120000});
    return jobs;
}

TEST(ShardPlan, CutsJobsIntoUnitsOfWholeVariants) {
    std::vector<ShardUnit> units = shardUnitsOf({{300, 2, 10}, {3, 1, 0}, {5, 0, 7}, {1, 600, 4}});
    // 256 items: 128 variants of 2 stages; a job's last unit holds the rest; a job without
    // stages has no unit; a variant with more stages than a unit's items is a unit of its own.
    EXPECT_EQ(units, (std::vector<ShardUnit>{{0, 0, 128, 256 * 10},
                                             {0, 128, 128, 256 * 10},
                                             {0, 256, 44, 88 * 10},
                                             {1, 0, 3, 3},
                                             {3, 0, 1, 600 * 4}}));
}

TEST(ShardPlan, EveryVariantInExactlyOneShard) {
    std::vector<ShardJobSize> jobs = realisticJobs();
    for (uint32_t count : {1u, 2u, 3u, 7u}) {
        std::vector<std::vector<int>> owners(jobs.size());
        for (size_t j = 0; j < jobs.size(); ++j) owners[j].assign(jobs[j].variants, 0);
        for (uint32_t k = 1; k <= count; ++k) {
            std::vector<ShardUnit> units = unitsOfShard(jobs, {k, count});
            EXPECT_FALSE(units.empty()) << k << "/" << count;
            EXPECT_EQ(unitsOfShard(jobs, {k, count}), units);  // deterministic
            for (size_t u = 0; u < units.size(); ++u) {
                if (u > 0) {  // job then variant order
                    EXPECT_TRUE(units[u - 1].job < units[u].job ||
                                (units[u - 1].job == units[u].job &&
                                 units[u - 1].firstVariant < units[u].firstVariant));
                }
                for (size_t v = 0; v < units[u].variants; ++v)
                    ++owners[units[u].job][units[u].firstVariant + v];
            }
        }
        for (size_t j = 0; j < jobs.size(); ++j) {
            for (size_t v = 0; v < jobs[j].variants; ++v)
                ASSERT_EQ(owners[j][v], 1) << "job " << j << " variant " << v << " of " << count;
        }
    }
}

TEST(ShardPlan, SplitsAHugePassAndBalancesTheShards) {
    std::vector<ShardJobSize> jobs = realisticJobs();
    const size_t huge = jobs.size() - 1;
    std::vector<ShardUnit> all = shardUnitsOf(jobs);
    uint64_t total = 0, largest = 0;
    for (const ShardUnit& unit : all) {
        total += unit.cost;
        largest = std::max(largest, unit.cost);
    }
    for (uint32_t count : {2u, 3u, 8u}) {
        std::vector<uint64_t> load(count, 0);
        for (uint32_t k = 1; k <= count; ++k) {
            bool hasHuge = false;
            for (const ShardUnit& unit : unitsOfShard(jobs, {k, count})) {
                load[k - 1] += unit.cost;
                hasHuge = hasHuge || unit.job == huge;
            }
            EXPECT_TRUE(hasHuge) << "shard " << k << "/" << count << " has none of the huge pass";
        }
        uint64_t most = *std::max_element(load.begin(), load.end());
        uint64_t least = *std::min_element(load.begin(), load.end());
        EXPECT_LE(most - least, largest) << count;
        EXPECT_LE(most, total / count + largest) << count;
    }
}

}  // namespace
}  // namespace varc::driver
