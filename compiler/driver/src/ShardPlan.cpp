// SPDX-License-Identifier: Apache-2.0
// Which share of a build each shard of `varc build --shard K/N` preprocesses and compiles.
#include "varc/driver/ShardPlan.h"

#include <algorithm>
#include <charconv>
#include <numeric>
#include <queue>
#include <utility>

namespace varc::driver {

namespace {

std::optional<uint32_t> parseNumber(std::string_view text) {
    uint32_t value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size())
        return std::nullopt;
    return value;
}

}  // namespace

std::optional<ShardSpec> parseShardSpec(std::string_view text) {
    size_t slash = text.find('/');
    if (slash == std::string_view::npos) return std::nullopt;
    std::optional<uint32_t> index = parseNumber(text.substr(0, slash));
    std::optional<uint32_t> count = parseNumber(text.substr(slash + 1));
    if (!index || !count || *index < 1 || *index > *count || *count > kMaxShards) {
        return std::nullopt;
    }
    return ShardSpec{*index, *count};
}

std::vector<uint32_t> assignShards(const std::vector<uint64_t>& costs, uint32_t count) {
    std::vector<uint32_t> shardOf(costs.size(), 0);
    if (count <= 1) return shardOf;
    std::vector<size_t> order(costs.size());
    std::iota(order.begin(), order.end(), size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return costs[a] > costs[b]; });
    // (load, shard), smallest first: the least loaded shard, the lower one on a tie.
    using Load = std::pair<uint64_t, uint32_t>;
    std::priority_queue<Load, std::vector<Load>, std::greater<>> loads;
    for (uint32_t shard = 0; shard < count; ++shard) loads.push({0, shard});
    for (size_t item : order) {
        auto [load, shard] = loads.top();
        loads.pop();
        shardOf[item] = shard;
        loads.push({load + costs[item], shard});
    }
    return shardOf;
}

std::vector<ShardUnit> shardUnitsOf(const std::vector<ShardJobSize>& jobs, size_t unitItems) {
    std::vector<ShardUnit> units;
    for (size_t j = 0; j < jobs.size(); ++j) {
        const ShardJobSize& job = jobs[j];
        if (job.variants == 0 || job.stages == 0) continue;
        const size_t perUnit = std::max<size_t>(1, unitItems / job.stages);
        for (size_t first = 0; first < job.variants; first += perUnit) {
            size_t count = std::min(perUnit, job.variants - first);
            uint64_t items = static_cast<uint64_t>(count) * job.stages;
            units.push_back({j, first, count, items * std::max<uint64_t>(1, job.textBytes)});
        }
    }
    return units;
}

std::vector<ShardUnit> unitsOfShard(const std::vector<ShardJobSize>& jobs, ShardSpec shard,
                                    size_t unitItems) {
    std::vector<ShardUnit> units = shardUnitsOf(jobs, unitItems);
    if (shard.whole()) return units;
    std::vector<uint64_t> costs;
    costs.reserve(units.size());
    for (const ShardUnit& unit : units) costs.push_back(unit.cost);
    std::vector<uint32_t> shardOf = assignShards(costs, shard.count);
    std::vector<ShardUnit> mine;
    for (size_t u = 0; u < units.size(); ++u) {
        if (shardOf[u] + 1 == shard.index) mine.push_back(units[u]);
    }
    return mine;
}

}  // namespace varc::driver
