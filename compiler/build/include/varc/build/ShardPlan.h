// SPDX-License-Identifier: Apache-2.0
// Which distinct programs each shard of `varc build --shard K/N` compiles.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace varc::compiler {

// Shard |index| (1-based) of |count|; {1, 1} is the whole build.
struct ShardSpec {
    uint32_t index = 1;
    uint32_t count = 1;
    bool whole() const { return count == 1; }
    std::string text() const { return std::to_string(index) + "/" + std::to_string(count); }
};

// "K/N" with 1 <= K <= N <= kMaxShards; nullopt for anything else ("0/2", "3/2", "2", "a/b").
inline constexpr uint32_t kMaxShards = 4096;
std::optional<ShardSpec> parseShardSpec(std::string_view text);

// Assigns items of the given estimated |costs| to |count| shards, balanced: longest first,
// each to the shard with the least cost so far (ties: the lower shard; equal costs: the lower
// item). Returns the 0-based shard of each item. Depends only on |costs| and |count|, so every
// machine of a sharded build computes the same plan.
std::vector<uint32_t> assignShards(const std::vector<uint64_t>& costs, uint32_t count);

}  // namespace varc::compiler
