// SPDX-License-Identifier: Apache-2.0
// Which share of a build each shard of `varc build --shard K/N` preprocesses and compiles.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace varc::driver {

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

// A pass job as the shard plan sees it: what every machine of a sharded build knows before
// preprocessing anything.
struct ShardJobSize {
    size_t variants = 0;     // after skips and rules
    size_t stages = 0;       // stage programs per variant
    uint64_t textBytes = 0;  // the pass's expanded source
};

// Variants [firstVariant, firstVariant + variants) of pass job |job|, every stage: the unit a
// shard takes. The estimated cost is its (variant, stage) items times the text's bytes (each
// item is preprocessed and pruned unless an identical one was; glslang's time grows with the text).
struct ShardUnit {
    size_t job = 0;
    size_t firstVariant = 0;
    size_t variants = 0;
    uint64_t cost = 0;
    friend bool operator==(const ShardUnit&, const ShardUnit&) = default;
};

// At most this many (variant, stage) items per unit (at least one variant), so a pass with many
// variants still splits while a small pass keeps its shared preprocessings on one shard.
inline constexpr size_t kShardUnitItems = 256;

// Every job cut into units, in job then variant order (jobs without variants or stages have none).
std::vector<ShardUnit> shardUnitsOf(const std::vector<ShardJobSize>& jobs,
                                    size_t unitItems = kShardUnitItems);

// The units of |jobs| that shard |shard| takes (assignShards over the units' costs), in job
// then variant order. Every unit belongs to exactly one shard of |shard.count|; {1, 1} takes all.
std::vector<ShardUnit> unitsOfShard(const std::vector<ShardJobSize>& jobs, ShardSpec shard,
                                    size_t unitItems = kShardUnitItems);

}  // namespace varc::driver
