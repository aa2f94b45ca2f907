// SPDX-License-Identifier: Apache-2.0
// Which distinct programs each shard of `varc build --shard K/N` compiles.
#include "varc/build/ShardPlan.h"

#include <algorithm>
#include <charconv>
#include <numeric>
#include <queue>
#include <utility>

namespace varc::compiler {

namespace {

std::optional<uint32_t> parseNumber(std::string_view text) {
    uint32_t value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size()) return std::nullopt;
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

}  // namespace varc::compiler
